#include "backgroundGrid.H"

#include "application.H"

#include <algorithm>
#include <cmath>
#if defined(KOKKOS_ENABLE_CUDA)
#include <cuda_runtime.h>
#endif

namespace slide
{
namespace mpm
{

unsigned long long availableMemoryBytes()
{
    unsigned long long bytes = output::availableMemoryBytes();
#if defined(KOKKOS_ENABLE_CUDA)
    // The particles and the grid live on the GPU; the host keeps output snapshots.
    size_t freeBytes = 0, totalBytes = 0;
    if (cudaMemGetInfo(&freeBytes, &totalBytes) == cudaSuccess)
    {
        bytes = bytes > 0 ? std::min<unsigned long long>(bytes, freeBytes) : freeBytes;
    }
#endif
    return bytes;
}

unsigned long long BackgroundGrid::bytesFor(const long long nNodes)
{
    // One copy per thread where the scatter duplicates (OpenMP), none where it
    // adds atomically (CUDA, whose concurrency of some 10^5 threads would count
    // a 48 GB grid for a flume of 2400 particles).
    const unsigned long long copies =
        nodeScatterIsAtomic ? 1ull : static_cast<unsigned long long>(ExecutionSpace().concurrency()) + 1ull;
    // Nodal components, averaging and pressure sums with their duplicates, the
    // velocity and the shift; and the base's fill and the row above the base, 2 + 3 per
    // column with duplicates, where a window (fit) has at least 6 rows.
    const unsigned long long n = static_cast<unsigned long long>(nNodes);
    return 8ull*n*((nComponents + 2 + 2)*copies + 2 + 2) + 8ull*5ull*copies*(n/6 + 1);
}

bool BackgroundGrid::fit(double xmin, double xmax, double ymin, double ymax, unsigned long long maxBytes)
{
    // Quadratic B-splines reach 1.5 cells; one more keeps particles that move
    // during the step inside.
    const int a0 = static_cast<int>(std::floor((xmin - xOrigin)/d)) - 2;
    const int a1 = static_cast<int>(std::floor((xmax - xOrigin)/d)) + 3;
    const int b0 = static_cast<int>(std::floor(ymin/d)) - 2;
    const int b1 = static_cast<int>(std::floor(ymax/d)) + 3;
    wi0 = a0;
    wj0 = b0;
    wni = a1 - a0 + 1;
    wnj = b1 - b0 + 1;
    if (ni > 0 && a0 >= i0 && a1 < i0 + ni && b0 >= j0 && b1 < j0 + nj) return true;

    // Grow with a margin of a quarter of the window (at least 8 cells) each way.
    const int mi = std::max(8, wni/4), mj = std::max(8, wnj/4);
    const long long newNi = wni + 2ll*mi, newNj = wnj + 2ll*mj;
    if (bytesFor(newNi*newNj) > maxBytes) return false;
    i0 = a0 - mi;
    j0 = b0 - mj;
    ni = static_cast<int>(newNi);
    nj = static_cast<int>(newNj);
    nodal = NodeField("nodal", ni, nj, nComponents);
    nodalScatter = NodeScatter(nodal);
    velocity = NodeField("nodeVelocity", ni, nj, 2);
    averaging = NodeField("averaging", ni, nj, 2);
    averagingScatter = NodeScatter(averaging);
    pressureSums = NodeField("pressureSums", ni, nj, 2);
    pressureSumsScatter = NodeScatter(pressureSums);
    pressureSumsCurrent = false;
    baseFill = ColumnField("baseFill", ni, 2);
    baseFillScatter = ColumnScatter(baseFill);
    rowAboveBase = ColumnField("rowAboveBase", ni, 3);
    rowAboveBaseScatter = ColumnScatter(rowAboveBase);
    shift = NodeField("nodeShift", ni, nj, 2);
    return true;
}

} // namespace mpm
} // namespace slide
