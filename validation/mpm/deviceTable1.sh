#!/bin/bash
# Table 1 runs of slideMPM on a lent GPU (session 69): table1.py in lanes, each
# lane running its cases one after the other, every case in a copy of the
# repository of its own (table1.py keeps its rows beside itself), so that a run
# cut off by the call's limit loses that run alone. Give one lane: on an H200,
# Case 2 at H0/60 and H0/80 and Case 1 at H0/60 took 46, 94 and 76 s one after the
# other, but in three lanes at once none of them had ended after 290 s (processes
# take turns on a GPU; `device.md`, session 69).
#
#   validation/mpm/deviceTable1.sh BINARY OUTDIR LIMIT_S "CASE:CELLS[:END] ..." ["..." ...]
#
# Each further argument is a lane: a list of CASE:CELLS (4x4 particles) with an
# optional end time (table1.py --end-time). LIMIT_S stops every lane then.
# Writes OUTDIR/rows.json (the table1.json rows of every run that ended, with
# "lanes": how many lanes shared the GPU; a failed run's row holds the end of its
# log) and OUTDIR/<case>_<cells>.log (table1.py's output).
# Back here: validation/mpm/table1.py --import OUTDIR/rows.json.
set -u
bin="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; out="$(mkdir -p "$2" && cd "$2" && pwd)"; limit="$3"; shift 3
top="$(cd "$(dirname "$0")/../.." && pwd)"
export SLIDEFOAM_SLIDEMPM_BINARY="$bin" PYTHONUNBUFFERED=1
ldconfig -p | grep -q "libcudart.so.13 " || export LD_LIBRARY_PATH="$(dirname "$bin")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
lanes=$#
work="$(mktemp -d)"

lane() {
    for run in $1; do
        [ -f "$work/stop" ] && break
        IFS=: read -r c cells end <<< "$run"
        copy="$work/r${c}_$cells"
        mkdir -p "$copy"
        (cd "$top" && tar cf - --exclude=./.git --exclude=./platforms --exclude=./.device .) | tar xf - -C "$copy"
        rm -f "$copy/validation/mpm/table1.json"
        python3 "$copy/validation/mpm/table1.py" --cases "$c" --cells "$cells" --ppc 4 \
            ${end:+--end-time "$end"} > "$out/${c}_$cells.log" 2>&1
        rc=$?
        # A run stopped at the limit is no result: its FAILED row goes (its log stays).
        [ -f "$work/stop" ] && grep -Eq "^case +$c H0/$cells: FAILED" "$out/${c}_$cells.log" \
            && rm -f "$copy/validation/mpm/table1.json" && echo "(stopped at the limit)" >> "$out/${c}_$cells.log"
        echo "lane: case $c H0/$cells: table1.py exit $rc at $SECONDS s: $(grep -E "^case +$c H0/$cells:" "$out/${c}_$cells.log")"
    done
}

for l in "$@"; do lane "$l" & done
start=$SECONDS
while [ -n "$(jobs -rp | head -1)" ] && [ $((SECONDS - start)) -lt "$limit" ]; do sleep 2; done
if [ -n "$(jobs -rp | head -1)" ]; then
    echo "limit of $limit s reached: stopping the runs still going"
    touch "$work/stop"
    pkill -f "$bin" ; sleep 1
fi
wait 2> /dev/null

python3 - "$work" "$out/rows.json" "$lanes" <<'EOF'
import glob, json, os, sys
rows = []
for p in sorted(glob.glob(os.path.join(sys.argv[1], "r*", "validation", "mpm", "table1.json"))):
    for r in json.load(open(p)):
        r["lanes"] = int(sys.argv[3])
        rows.append(r)
json.dump(rows, open(sys.argv[2], "w"), indent=1)
print("%d rows in %s" % (len(rows), sys.argv[2]))
for r in rows:
    print("case %2d H0/%d: %s" % (r["case"], r["cells"], r.get("runout", "FAILED")), r.get("atRest"), r.get("endTime"),
          r.get("wall"), r.get("backend"))
EOF
