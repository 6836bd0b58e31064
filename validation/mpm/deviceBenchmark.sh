#!/bin/bash
# slideMPM on a GPU machine: the CUDA backend's scene tests, then the
# Krone-Wright flume (to 4.1 s) at several set-ups, then Table 1 cases (CASES),
# each with its wall time, particle-updates per second and front position;
# the same flume set-ups on the host's OpenMP cores for comparison.
# Binaries are built here (bin/tools/slidefoam-build-cuda, ./Allwmake) and
# carried to the GPU machine; nothing is compiled there.
#
#   validation/mpm/deviceBenchmark.sh cuda|openmp BINARY OUTDIR [CELLSxPPC ...]
#
# Writes OUTDIR/<backend>_<set-up>.json (the run's summary.json) and prints a
# table row per run: backend, set-up, wall time, particle-updates/s, front.
# RUN_TIMEOUT (seconds, default 600) stops a run that would take longer;
# CASES lists the Table 1 runs (default case09:10x2:20; empty for none);
# MPMDICT_EXTRA is added to each run's mpmDict (e.g. "phaseTimes yes;");
# FLUME_END (default 4.1) ends the flume runs earlier; the set-up `none` runs
# no flume.
set -u
backend="$1"; bin="$2"; out="$3"; shift 3
setups="${*:-10x2 20x2 30x4 60x4}"
[ "$setups" = none ] && setups=""
top="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
mkdir -p "$out"

runCase() {  # src tag cells ppc endTime
    local src="$1" tag="$2" cells="$3" ppc="$4" end="$5"
    local d="$work/$tag"
    rm -rf "$d"; cp -r "$src" "$d"; rm -rf "$d/postProcessing" "$d"/log.*
    if [ "$cells" = tutorial ]; then   # the tutorial's own set-up (a shear band, say), no fields written
        sed -i "s/^writeFields .*/writeFields no;/" "$d/system/mpmDict"
    else
        printf 'setting fast;\ncellsPerHeight %d;\nparticlesPerCell %d;\nwriteFields no;\nprogressInterval 30;\n' \
            "$cells" "$ppc" > "$d/system/mpmDict"
    fi
    [ -z "${MPMDICT_EXTRA:-}" ] || printf '%s\n' "$MPMDICT_EXTRA" >> "$d/system/mpmDict"
    sed -i "s/^endTime .*/endTime $end;/" "$d/system/controlDict"
    if timeout "${RUN_TIMEOUT:-600}" "$bin" -case "$d" > "$out/log.${backend}_$tag" 2>&1; then
        cp "$d/postProcessing/slideMPM/summary.json" "$out/${backend}_$tag.json"
        python3 - "$out/${backend}_$tag.json" "$backend" "$tag" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
print("%-8s %-16s wall %8.1f s  %.3e particle-updates/s  %9d particles  front/runout %.3f m  [%s]" % (
    sys.argv[2], sys.argv[3], s["wall_time_s"], s["particle_updates_per_second"], s["problem_size"],
    s.get("final_length_m", s["runout_m"]) if "flume" in sys.argv[3] else s["runout_m"], s["backend"]))
EOF
    else
        echo "$backend $tag FAILED:"; tail -5 "$out/log.${backend}_$tag"
    fi
}

for s in $setups; do
    runCase "$top/tutorials/kroneWrightRun15" "flume_$s" "${s%x*}" "${s#*x}" "${FLUME_END:-4.1}"
done
# Table 1 cases, CASE:CELLSxPPC:ENDTIME each, or CASE:tutorial:ENDTIME for the
# tutorial's own mpmDict.
for c in ${CASES-case09:10x2:20}; do
    IFS=: read -r name setup end <<< "$c"
    if [ "$setup" = tutorial ]; then
        runCase "$top/tutorials/table1/$name" "${name}_tutorial" tutorial 0 "$end"
    else
        runCase "$top/tutorials/table1/$name" "${name}_$setup" "${setup%x*}" "${setup#*x}" "$end"
    fi
done
rm -rf "$work"
