#!/bin/bash
# slideMPM's whole check on a lent GPU machine, in one call: the machine, the
# CUDA backend's scene tests, the Krone-Wright flume and Table 1 Case 9 on CUDA,
# then the same runs with OpenMP on the machine's own cores. Nothing is compiled
# there: BINDIR holds what was built here for the GPU's generation
#   bin/tools/slidefoam-build-cuda --arch HOPPER90
#   BINDIR/slideMPM-cuda, BINDIR/mpmSceneTest-cuda, BINDIR/slideMPM-openmp
# and libgomp.so.1 and libcudart.so.13, used only where the machine lacks one.
#
#   validation/mpm/deviceCheck.sh BINDIR OUTDIR
#
# BINDIR from a build here, e.g. (the folder ignored by git, carried to the GPU):
#   bin/tools/slidefoam-build-cuda --arch HOPPER90; o=platforms/$SLIDEFOAM_OPTIONS; mkdir -p .device
#   cp $o/bin-cuda/slideMPM .device/slideMPM-cuda; cp $o/bin/slideMPM .device/slideMPM-openmp
#   cp $o/cmake-cuda/applications/solvers/slideMPM/mpmSceneTest .device/mpmSceneTest-cuda
#   cp -L /lib/x86_64-linux-gnu/libgomp.so.1 /usr/local/cuda/lib64/libcudart.so.13 .device/
#
# OUTDIR gets machine.txt, sceneTests.log, the runs' logs and summaries
# (deviceBenchmark.sh) and results.txt, one line per run; each phase has its
# own time limit so that a slow one leaves the others their time; a smoke run
# that hangs ends the check with cuda-gdb's view of where. PROFILE=no leaves out
# the kernel times (ncu, profile.log); OPENMP=no leaves out the OpenMP runs.
set -u
bin="$(cd "$1" && pwd)"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
for lib in libgomp.so.1 libcudart.so.13; do
    ldconfig -p | grep -q "$lib " || { export LD_LIBRARY_PATH="$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"; break; }
done
{
    nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm,clocks.max.mem --format=csv
    echo "host cores: $(nproc); $(grep -m1 'model name' /proc/cpuinfo)"
} > "$out/machine.txt" 2>&1
cat "$out/machine.txt"

echo "== CUDA smoke run: the flume at H0/10 with 2x2 particles, ${SMOKE_TIMEOUT:-40} s at most"
# A run that does not end in time is stopped inside cuda-gdb (SIGINT), which
# prints the kernel on the GPU and the host's stack: where it hangs.
smoke="$(mktemp -d)"
cp -r "$here/../../tutorials/kroneWrightRun15" "$smoke/case"
rm -rf "$smoke/case/postProcessing" "$smoke/case"/log.*
printf 'setting fast;\ncellsPerHeight 10;\nparticlesPerCell 2;\nwriteFields no;\nprogressInterval 2;\n' \
    > "$smoke/case/system/mpmDict"
sed -i "s/^endTime .*/endTime 4.1;/" "$smoke/case/system/controlDict"
if command -v cuda-gdb > /dev/null; then
    cuda-gdb -q -batch -ex run -ex 'info cuda kernels' -ex 'thread apply all bt 12' -ex kill \
        --args "$bin/slideMPM-cuda" -case "$smoke/case" > "$out/smoke.log" 2>&1 &
else
    "$bin/slideMPM-cuda" -case "$smoke/case" > "$out/smoke.log" 2>&1 &
fi
runner=$!
for i in $(seq "${SMOKE_TIMEOUT:-40}"); do kill -0 $runner 2> /dev/null || break; sleep 1; done
if kill -0 $runner 2> /dev/null; then
    pkill -INT -f "slideMPM-cuda -case $smoke/case"
    sleep 20; kill -9 $runner 2> /dev/null; pkill -9 -f "slideMPM-cuda -case $smoke/case"
    echo "smoke run HUNG:"; grep -v '^Time = ' "$out/smoke.log" | tail -60
    exit 1
fi
tail -4 "$out/smoke.log"

echo "== CUDA runs"
RUN_TIMEOUT="${RUN_TIMEOUT:-150}" "$here/deviceBenchmark.sh" cuda "$bin/slideMPM-cuda" "$out" ${CUDA_SETUPS:-10x2 20x2 30x4 60x4} \
    | tee -a "$out/results.txt"


echo "== CUDA scene tests"
start=$SECONDS
timeout "${TEST_TIMEOUT:-150}" "$bin/mpmSceneTest-cuda" > "$out/sceneTests.log" 2>&1
echo "exit $? after $((SECONDS - start)) s"; grep -E '^\[  (PASSED|FAILED) |^\[==========\]' "$out/sceneTests.log"

if [ "${PROFILE:-yes}" = yes ] && command -v ncu > /dev/null; then
    # Where a step's GPU time goes: each kernel's duration (one metric, so one
    # pass per launch) over PROFILE_LAUNCHES launches of the flume at
    # PROFILE_SETUP (CELLSxPPC, default 30x4) after the first PROFILE_SKIP
    # (set-up and the first steps).
    psetup="${PROFILE_SETUP:-30x4}"
    echo "== CUDA kernel times (ncu, flume $psetup)"
    prof="$(mktemp -d)"
    cp -r "$here/../../tutorials/kroneWrightRun15" "$prof/case"
    rm -rf "$prof/case/postProcessing" "$prof/case"/log.*
    printf 'setting fast;\ncellsPerHeight %d;\nparticlesPerCell %d;\nwriteFields no;\nprogressInterval 30;\n' \
        "${psetup%x*}" "${psetup#*x}" > "$prof/case/system/mpmDict"
    sed -i "s/^endTime .*/endTime 0.5;/" "$prof/case/system/controlDict"
    timeout "${PROFILE_TIMEOUT:-90}" ncu --clock-control none --metrics gpu__time_duration.sum \
        --launch-skip "${PROFILE_SKIP:-2000}" --launch-count "${PROFILE_LAUNCHES:-400}" --print-summary per-kernel \
        "$bin/slideMPM-cuda" -case "$prof/case" > "$out/profile.log" 2>&1
    echo "exit $?"; grep -v '^==PROF==' "$out/profile.log" | cut -c1-160 | tail -50
fi

[ "${OPENMP:-yes}" = no ] && exit 0
echo "== OpenMP runs ($(nproc) threads)"
export OMP_NUM_THREADS="$(nproc)" OMP_PROC_BIND=spread OMP_PLACES=cores
RUN_TIMEOUT="${RUN_TIMEOUT:-150}" "$here/deviceBenchmark.sh" openmp "$bin/slideMPM-openmp" "$out" ${OPENMP_SETUPS:-10x2 20x2 30x4 60x4} \
    | tee -a "$out/results.txt"
