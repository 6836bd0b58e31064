#!/bin/bash
# slideMPM's speed on a lent GPU, in one call (session 64): the flume at four
# set-ups with the defaults, the CUDA scene tests, then the phase times of the
# paper's set-up (H0/60, 4x4) to FLUME_END s under each variant of the choices
# that session made (nodeSums, blockParticles, writeInBackground), then the
# kernel times (ncu) of both particle-to-grid transfers. Nothing is compiled
# there: BINDIR holds slideMPM-cuda and mpmSceneTest-cuda built here
# (bin/tools/slidefoam-build-cuda --arch HOPPER90), and libcudart.so.13, used
# only where the machine lacks one.
#
#   validation/mpm/deviceSpeed.sh BINDIR OUTDIR
#
# SETUPS (the headline flume set-ups), PHASE_SETUP (60x4) and FLUME_END (1)
# change what runs; OUTDIR: machine.txt, results.txt (a line per run), phases.txt (each
# variant's phase table), sceneTests.log, profile.log, and a folder per group
# of runs with each run's log and summary.json (deviceBenchmark.sh).
set -u
bin="$(cd "$1" && pwd)"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
ldconfig -p | grep -q "libcudart.so.13 " || export LD_LIBRARY_PATH="$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
{
    nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm,clocks.max.mem --format=csv
    echo "host cores: $(nproc); $(grep -m1 'model name' /proc/cpuinfo)"
} > "$out/machine.txt" 2>&1
cat "$out/machine.txt"
bench="$here/deviceBenchmark.sh"
export CASES=""

echo "== the flume, the defaults (nodeSums perParticle, writeInBackground yes on a GPU)"
RUN_TIMEOUT=90 "$bench" cuda "$bin/slideMPM-cuda" "$out/defaults" ${SETUPS:-10x2 20x2 30x4 60x4} | tee -a "$out/results.txt"

echo "== CUDA scene tests"
start=$SECONDS
timeout "${TEST_TIMEOUT:-120}" "$bin/mpmSceneTest-cuda" > "$out/sceneTests.log" 2>&1
echo "exit $? after $((SECONDS - start)) s"
grep -E '^\[  (PASSED|FAILED) |^\[==========\]|^blocks of' "$out/sceneTests.log"

ps="${PHASE_SETUP:-60x4}"
echo "== phase times, flume $ps to ${FLUME_END:=1} s"
for v in "perParticle:" "blocks128:nodeSums perBlock;" "foreground:writeInBackground no;" \
         "blocks64:nodeSums perBlock; blockParticles 64;" "blocks256:nodeSums perBlock; blockParticles 256;"; do
    name="${v%%:*}"
    MPMDICT_EXTRA="phaseTimes yes; ${v#*:}" FLUME_END="$FLUME_END" RUN_TIMEOUT=60 \
        "$bench" cuda "$bin/slideMPM-cuda" "$out/$name" "$ps" | sed "s/^/$name: /" | tee -a "$out/results.txt"
    { echo "== $name (${v#*:})"; sed -n '/^Phase times/,/^$/p' "$out/$name/log.cuda_flume_$ps"; } >> "$out/phases.txt"
done
cat "$out/phases.txt"

if command -v ncu > /dev/null; then
    echo "== kernel times (ncu), H0/60 4x4, both particle-to-grid transfers"
    for v in "perBlock" "perParticle"; do
        prof="$(mktemp -d)"
        cp -r "$here/../../tutorials/kroneWrightRun15" "$prof/case"
        rm -rf "$prof/case/postProcessing" "$prof/case"/log.*
        printf 'setting fast;\ncellsPerHeight 60;\nparticlesPerCell 4;\nwriteFields no;\nwriteState no;\nnodeSums %s;\n' "$v" \
            > "$prof/case/system/mpmDict"
        sed -i "s/^endTime .*/endTime 0.05;/" "$prof/case/system/controlDict"
        timeout "${PROFILE_TIMEOUT:-60}" ncu --clock-control none --metrics gpu__time_duration.sum \
            --launch-skip 100 --launch-count 200 --print-summary per-kernel \
            "$bin/slideMPM-cuda" -case "$prof/case" > "$out/profile_$v.log" 2>&1
        echo "$v: exit $?, average us per launch:"
        awk '/cuda_parallel_launch/ {name = $0} /gpu__time_duration.sum/ {printf "%10s  %s\n", $NF, substr(name, 1, 150)}' \
            "$out/profile_$v.log" | sort -rn | head -12
    done
fi
