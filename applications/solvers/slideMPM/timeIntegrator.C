// The step: the particle-to-grid and grid-to-particle transfers, and the step
// that chains them with the grid's update (gridUpdate.C) and the particles'
// stress update (stressUpdate.C).
#include "timeIntegrator.H"
#include "cellPressure.H"
#include "quadraticBSpline.H"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slide
{
namespace mpm
{

namespace
{

// Particle-to-grid transfer: mass, momentum (the particle's velocity field at
// the node, gravity's impulse and the internal force's) and volume.
// What both transfers read: the particles' fields, the grid's place, the step
// and the transfer's kind.
struct TransferSetup
{
    ParticleVector x, v, Q;       // Q: the quadratic mode's coefficient
    ParticleTensor C;
    ParticleScalar m, V;
    double invD, xOrigin, dt;
    int i0, j0;
    RowShear rows;                // the rows' base where they follow a polyline base
    bool apic, fittedBase;
    bool allQuadratic;            // the quadratic transfer: every particle's mode

    TransferSetup() = default;
    TransferSetup(const MaterialPoints& mp, const BackgroundGrid& grid, const double dt_,
                  const MpmControls::Transfer transfer, const bool fitted)
    :
        x(mp.position), v(mp.velocity), Q(mp.quadraticMode), C(mp.affine), m(mp.mass), V(mp.volume),
        invD(1.0/grid.d), xOrigin(grid.xOrigin), dt(dt_), i0(grid.i0), j0(grid.j0), rows(grid.rows),
        apic(transfer != MpmControls::Transfer::pic), fittedBase(fitted),
        allQuadratic(transfer == MpmControls::Transfer::quadratic)
    {}
};

// Where a particle's node contributions go.
// Into the grid through the ScatterView: a copy per thread on the host, atomics on a GPU.
template<class Access>
struct ScatterTarget
{
    Access acc;
    KOKKOS_FORCEINLINE_FUNCTION void operator()(const int i, const int j, const Quad& q) const { addToNode(acc, i, j, q); }
};

// Into the grid with one atomic add per component (nodes outside a block's tile).
struct AtomicTarget
{
    NodeField nodal;
    KOKKOS_FORCEINLINE_FUNCTION void operator()(const int i, const int j, const Quad& q) const
    {
        for (int c = 0; c < 4; ++c) Kokkos::atomic_add(&nodal(i, j, c), q[c]);
    }
};

// Into a block's tile of nodes [i0, i0 + ni) x [j0, j0 + nj) in its scratch
// (shared) memory, laid out as the grid's nodes are; a node outside it, into
// the grid.
struct TileTarget
{
    double* tile;
    int i0, j0, ni, nj;
    AtomicTarget outside;
    KOKKOS_FORCEINLINE_FUNCTION void operator()(const int i, const int j, const Quad& q) const
    {
        const int ti = i - i0, tj = j - j0;
        if (ti < 0 || ti >= ni || tj < 0 || tj >= nj) return outside(i, j, q);
        double* node = tile + 4*(ti*nj + tj);
        for (int c = 0; c < 4; ++c) Kokkos::atomic_add(node + c, q[c]);
    }
};

struct ParticleToGrid : TransferSetup
{
    NodeScatter scatter;
    NodeField avg;                // B-bar: the cell's mean pressure (0) and its particles' volume (1)
    ParticleTensor sig;
    double d, gX, gY;
    bool cellPressure;
    bool cellCapped = false;      // MpmControls::StressQuadrature::cellCapped
    ColumnScatter baseFill;       // touching base contact: BackgroundGrid::baseFill
    ParticleVector size;          // the particles' domains
    bool fill = false;
    ColumnScatter rowAbove;       // BackgroundGrid::rowAboveBase, where scaleRowAbove
    double modulus = 0.0;         // the constrained modulus lambda + 2G [Pa]
    bool scaleRowAbove = false;

    KOKKOS_INLINE_FUNCTION void operator()(const int p) const
    {
        const ScatterTarget<decltype(scatter.access())> add{scatter.access()};
        scatterOne(p, add);
    }

    // Particle p's contributions, each node's handed to add(i, j, Quad).
    template<class Add>
    KOKKOS_FORCEINLINE_FUNCTION void scatterOne(const int p, const Add& add) const
    {
        if (allQuadratic) scatterParticle<true>(p, add);
        else scatterParticle<false>(p, add);
    }

    template<bool AllQuadratic, class Add>
    KOKKOS_FORCEINLINE_FUNCTION void scatterParticle(const int p, const Add& add) const
    {
        const double xp = x(p, 0), slope = rows.slope(xp);
        const Stencil st(xp, x(p, 1) - rows.height(xp), xOrigin, invD, i0, j0, fittedBase, AllQuadratic);
        const int bx = st.bx, by = st.by;
        const double fx = st.fx;
        const double *wx = st.wx, *dwx = st.dwx, *wy = st.wy, *dwy = st.dwy;
        const double mp_ = m(p), Vp = V(p);
        double sxx = sig(p, 0), syy = sig(p, 1);
        const double sxy = sig(p, 3);
        double Vq = Vp;   // the particle's weight in the internal force
        if (cellPressure)
        {
            // B-bar: the force sees the cell's mean pressure, as the stress update
            // sees the cell's mean dilatation, so the two stay work-conjugate.
            const int ci = st.cellX(), cj = st.cellY();
            const double shift = -UndrainedClay::third*(sxx + syy + sig(p, 2)) - avg(ci, cj, 0);   // the cell's mean
            sxx += shift;
            syy += shift;
            if (cellCapped && avg(ci, cj, 1) > d*d) Vq *= d*d/avg(ci, cj, 1);
        }
        const double vx = v(p, 0), vy = v(p, 1);
        const double C00 = C(p, 0)*d, C01 = C(p, 1)*d, C10 = C(p, 2)*d, C11 = C(p, 3)*d;
        const double Sxx = dt*Vq*sxx*invD, Syy = dt*Vq*syy*invD, Sxy = dt*Vq*sxy*invD;
        // Node (a, b) receives, over its components (mass, momentum x and y, volume),
        // w P + w dx PDx + w dy PDy + w q PQ + gx PGx + gy PGy (dx, dy: node -
        // particle in cells; q: the quadratic mode; gx, gy: weight gradients per
        // cell, 1/d is in S). The weights are products of x and y factors, so
        // each row a is combined once and its three nodes take a few
        // multiply-adds of 4-vectors (one SIMD register on the host).
        const Quad P = Quad::of({mp_, mp_*(vx + dt*gX), mp_*(vy + dt*gY), Vp});   // momentum with gravity's impulse
        const Quad PDx = Quad::of({0.0, mp_*C00, mp_*C10, 0.0});
        const Quad PDy = Quad::of({0.0, mp_*C01, mp_*C11, 0.0});
        const Quad PGx = Quad::of({0.0, -Sxx, -Sxy, 0.0});
        // Under sheared rows a weight's x derivative is dN/dx - b'(x) dN/dy
        // (lattice derivatives): its share moves into the y term.
        const Quad PGy = Quad::of({0.0, -(Sxy - slope*Sxx), -(Syy - slope*Sxy), 0.0});
        const bool modeHere = AllQuadratic || (apic && st.quadratic);
        const Quad PQ = modeHere ? Quad::of({0.0, mp_*Q(p, 0), mp_*Q(p, 1), 0.0}) : Quad::broadcast(0.0);
        if (AllQuadratic)
        {
            for (int a = 0; a < 3; ++a)
            {
                const Quad row = wx[a]*P + (wx[a]*(a - fx))*PDx + dwx[a]*PGx;
                const Quad rowDy = wx[a]*PDy, rowGy = wx[a]*PGy, rowQ = wx[a]*PQ;
                for (int b = 0; b < 3; ++b)
                {
                    add(bx + a, by + b, wy[b]*row + (wy[b]*st.dy[b])*rowDy + (wy[b]*st.q[b])*rowQ + dwy[b]*rowGy);
                }
            }
        }
        else
        {
            for (int a = 0; a < 3; ++a)
            {
                const Quad row = wx[a]*P + (wx[a]*(a - fx))*PDx + dwx[a]*PGx;
                const Quad rowDy = wx[a]*PDy, rowGy = wx[a]*PGy;
                for (int b = 0; b < 3; ++b)
                {
                    add(bx + a, by + b, wy[b]*row + (wy[b]*st.dy[b])*rowDy + dwy[b]*rowGy);
                }
            }
            if (modeHere)
            {
                for (int a = 0; a < 3; ++a)
                {
                    for (int b = 0; b < 3; ++b) add(bx + a, by + b, (wx[a]*wy[b]*st.q[b])*PQ);
                }
            }
        }
        // The row above a fitted base's node: absolute row 0, the particle's
        // row b when its first row is 0 - b.
        const int bAbove = -j0 - by;
        if (scaleRowAbove && bAbove >= 0 && bAbove < 3) addRowAbove(bx, bAbove, st, Vp, slope, Sxx, Syy, Sxy);
        if (st.baseSpan)
        {
            // The base's nodes count the volume of the cell on the base with the
            // particles' x weights alone (d^2 per column under a slide, wherever
            // in the cell the particles sit): the share of the base the slide
            // covers. Their y weights, (1 - s)^2, would undercount it by the
            // midpoint rule's error (6 % with 2 x 2 particles).
            const double Vb = Vp*(1.0 - wy[0]);
            for (int a = 0; a < 3; ++a) add(bx + a, by, Quad::of({0.0, 0.0, 0.0, wx[a]*Vb}));
            if (fill) addBaseFill(p, bx, wx);
        }
    }

    // The row above the base: the node's diagonal stiffness, modulus V |grad N|^2
    // (an upper bound on its own frequency's square times its mass, B-bar or
    // not), and the internal force's impulse, as scattered above (S: dt V sigma/d).
    KOKKOS_INLINE_FUNCTION void addRowAbove(const int bx, const int b, const Stencil& st, const double Vp,
                                            const double slope, const double Sxx, const double Syy,
                                            const double Sxy) const
    {
        auto acc = rowAbove.access();
        for (int a = 0; a < 3; ++a)
        {
            const double gx = st.dwx[a]*st.wy[b], gy = st.wx[a]*st.dwy[b];   // lattice, per cell
            const double gxs = gx - slope*gy;
            acc(bx + a, 0) += modulus*Vp*invD*invD*(gxs*gxs + gy*gy);
            acc(bx + a, 1) -= gx*Sxx + gy*(Sxy - slope*Sxx);
            acc(bx + a, 2) -= gx*Sxy + gy*(Syy - slope*Sxy);
        }
    }

    // The particle's domain (its height, at most a cell) split between the
    // base cell's lowest strip and the rest of the cell, as volume; a domain
    // reaching below the base (a particle put back on it) counts from the base up.
    KOKKOS_INLINE_FUNCTION void addBaseFill(const int p, const int bx, const double* wx) const
    {
        const double y = x(p, 1) - rows.height(x(p, 0));
        const double h = size(p, 1) < d ? size(p, 1) : d;
        if (!(h > 0.0)) return;
        const double lo = y - 0.5*h > 0.0 ? y - 0.5*h : 0.0, hi = lo + h;
        const double strip = baseTouchStrip*d;
        const double inLowest = (hi < strip ? hi : strip) - (lo < strip ? lo : strip);
        const double inRest = (hi < d ? hi : d) - (lo > strip ? lo : strip);
        const double Vp = V(p)/h;
        auto acc = baseFill.access();
        for (int a = 0; a < 3; ++a)
        {
            if (inLowest > 0.0) acc(bx + a, 0) += wx[a]*Vp*inLowest;
            if (inRest > 0.0) acc(bx + a, 1) += wx[a]*Vp*inRest;
        }
    }
};

// Particle-to-grid by blocks (MpmControls::NodeSums::perBlock). The particles
// are sorted by cell every sortInterval steps, so a block's run of them covers
// a strip of a few cells. The block first finds the nodes its particles reach,
// sums their contributions into that tile in its scratch (on a GPU, shared)
// memory, and then adds the tile to the grid: one atomic add per node and
// component and block, where perParticle makes 36 per particle, most of them
// onto the same few nodes as the particles beside it. A run that reaches
// beyond `capacity` nodes (particles split since the last sort) adds straight
// into the grid.
struct BlockParticleToGrid
{
    using Team = Kokkos::TeamPolicy<ExecutionSpace>::member_type;
    ParticleToGrid f;
    NodeField nodal;
    int count = 0;
    int block = 0;      // particles per block
    int capacity = 0;   // nodes of a tile

    KOKKOS_INLINE_FUNCTION static size_t scratchBytes(const int capacity) { return 4*sizeof(double)*capacity; }

    KOKKOS_INLINE_FUNCTION void operator()(const Team& team) const
    {
        const int p0 = team.league_rank()*block;
        const int p1 = p0 + block < count ? p0 + block : count;
        double* tile = static_cast<double*>(team.team_shmem().get_shmem(scratchBytes(capacity)));
        const TransferSetup& ts = f;
        // The range of the block's first supporting nodes along the grid's axis 0 (x) or 1 (y).
        auto nodeRange = [&](const int axis)
        {
            Kokkos::MinMaxScalar<int> range;
            Kokkos::parallel_reduce(Kokkos::TeamThreadRange(team, p0, p1), [&](const int p, Kokkos::MinMaxScalar<int>& r)
            {
                int b[2];
                firstNodes(ts, p, b[0], b[1]);
                if (b[axis] < r.min_val) r.min_val = b[axis];
                if (b[axis] > r.max_val) r.max_val = b[axis];
            }, Kokkos::MinMax<int>(range));
            return range;
        };
        const Kokkos::MinMaxScalar<int> rx = nodeRange(0), ry = nodeRange(1);
        const int ni = rx.max_val - rx.min_val + 3, nj = ry.max_val - ry.min_val + 3;
        const AtomicTarget grid{nodal};
        if (p1 <= p0 || ni*nj > capacity)
        {
            Kokkos::parallel_for(Kokkos::TeamThreadRange(team, p0, p1), [&](const int p) { f.scatterOne(p, grid); });
            return;
        }
        Kokkos::parallel_for(Kokkos::TeamThreadRange(team, 4*ni*nj), [&](const int k) { tile[k] = 0.0; });
        team.team_barrier();
        const TileTarget add{tile, rx.min_val, ry.min_val, ni, nj, grid};
        Kokkos::parallel_for(Kokkos::TeamThreadRange(team, p0, p1), [&](const int p) { f.scatterOne(p, add); });
        team.team_barrier();
        // Node by node and component by component: neighbouring threads add to neighbouring addresses.
        Kokkos::parallel_for(Kokkos::TeamThreadRange(team, 4*ni*nj), [&](const int k)
        {
            const double value = tile[k];
            const int node = k/4;
            if (value != 0.0) Kokkos::atomic_add(&nodal(add.i0 + node/nj, add.j0 + node%nj, k%4), value);
        });
    }

    // The first of the 3 x 3 nodes supporting particle p (Stencil's bx, by).
    KOKKOS_FORCEINLINE_FUNCTION static void firstNodes(const TransferSetup& ts, const int p, int& bx, int& by)
    {
        const double xp = ts.x(p, 0);
        Stencil::firstNodes(xp, ts.x(p, 1) - ts.rows.height(xp), ts.xOrigin, ts.invD, ts.i0, ts.j0, ts.fittedBase,
                            bx, by);
    }
};

// Grid-to-particle transfer (velocity, APIC affine field, velocity gradient) with the B-bar's cell sums of the dilatation
// and the step's reductions (bounding box, speed, kinetic energy, downslope momentum, finiteness) in the same pass.
struct GridToParticle : TransferSetup
{
    typedef double value_type[];
    enum { xmax = 0, negXmin, ymax, negYmin, speed2, nonFinite, kinetic, momentumX, nStats };
    const unsigned value_count = nStats;

    ParticleTensor L;
    NodeField vel;
    NodeScatter cellDilatation;   // B-bar: the cell sums of V tr(L) and V
    double twoCells;              // [m]: below it, a particle may be in the base's cell at the next particle-to-grid
    int count;
    bool average;

    // A work item is a run of particlesPerItem particles, whose statistics are
    // gathered in registers and merged into the thread's once.
    KOKKOS_INLINE_FUNCTION void operator()(const int item, value_type s) const
    {
        double hi[5] = {s[xmax], s[negXmin], s[ymax], s[negYmin], s[speed2]};
        double ke = s[kinetic], px = s[momentumX];
        bool finite = true;
        const int end = (item + 1)*particlesPerItem < count ? (item + 1)*particlesPerItem : count;
        for (int p = item*particlesPerItem; p < end; ++p)
        {
            double nx, ny, v2;
            if (allQuadratic) transfer<true>(p, nx, ny, v2);
            else transfer<false>(p, nx, ny, v2);
            finite = finite && std::isfinite(nx) && std::isfinite(ny) && std::isfinite(v2);
            hi[0] = nx > hi[0] ? nx : hi[0];
            hi[1] = -nx > hi[1] ? -nx : hi[1];
            hi[2] = ny > hi[2] ? ny : hi[2];
            hi[3] = -ny > hi[3] ? -ny : hi[3];
            hi[4] = v2 > hi[4] ? v2 : hi[4];
            ke += 0.5*m(p)*v2;
            px += m(p)*v(p, 0);
        }
        s[xmax] = hi[0]; s[negXmin] = hi[1]; s[ymax] = hi[2]; s[negYmin] = hi[3]; s[speed2] = hi[4];
        s[kinetic] = ke;
        s[momentumX] = px;
        if (!finite) s[nonFinite] = 1.0;
    }

    // Particle p's transfer; nx, ny: where it is going, v2: its speed squared.
    template<bool AllQuadratic>
    KOKKOS_FORCEINLINE_FUNCTION void transfer(const int p, double& nx, double& ny, double& v2) const
    {
        const double xp = x(p, 0), yRow = x(p, 1) - rows.height(xp);
        const Stencil st(xp, yRow, xOrigin, invD, i0, j0, fittedBase, AllQuadratic);
        const int bx = st.bx, by = st.by;
        const double fx = st.fx;
        const double *wx = st.wx, *dwx = st.dwx, *wy = st.wy, *dwy = st.dwy;
        // The weights are products of x and y factors: each node row a is summed
        // over b first (value, y-derivative, y-moment; both velocity components
        // side by side), then the rows over a: 84 multiply-adds instead of 117.
        const Pair zero = Pair::broadcast(0.0);
        Pair u = zero, Bx = zero, By = zero, Gx = zero, Gy = zero, Bq = zero;
        const double wyDy[3] = {wy[0]*st.dy[0], wy[1]*st.dy[1], wy[2]*st.dy[2]};   // node - particle, in cells
        double wyQ[3] = {0.0, 0.0, 0.0};
        if (AllQuadratic) for (int b = 0; b < 3; ++b) wyQ[b] = wy[b]*st.q[b];
        for (int a = 0; a < 3; ++a)
        {
            Pair row = zero, rowDy = zero, rowMoment = zero, rowQ = zero;
            for (int b = 0; b < 3; ++b)
            {
                const Pair un = Pair::load(&vel(bx + a, by + b, 0));
                row += wy[b]*un;
                rowDy += dwy[b]*un;
                rowMoment += wyDy[b]*un;
                if (AllQuadratic) rowQ += wyQ[b]*un;
            }
            u += wx[a]*row;
            Bx += (wx[a]*(a - fx))*row;
            By += wx[a]*rowMoment;
            Gx += dwx[a]*row;   // per cell
            Gy += wx[a]*rowDy;
            if (AllQuadratic) Bq += wx[a]*rowQ;
        }
        // The velocity gradient in x and y from the lattice's (sheared rows:
        // d/dx = d/dx_lattice - b'(x) d/dy); APIC's affine field stays the
        // lattice's, as its moments are.
        if (rows.on) Gx += (-rows.slope(xp))*Gy;
        const double vx = u[0], vy = u[1];
        const double L00 = Gx[0], L01 = Gy[0], L11 = Gy[1];
        // B is in cells: 4/d^2 * d (D_yy differs in the base's span of a fitted base).
        const double k = apic ? QuadraticBSpline::apicInverseFactor*invD : 0.0;
        const double ky = apic ? st.apicY*invD : 0.0;
        C(p, 0) = k*Bx[0]; C(p, 1) = ky*By[0]; C(p, 2) = k*Bx[1]; C(p, 3) = ky*By[1];
        if (AllQuadratic)
        {
            Q(p, 0) = st.invQ*Bq[0];
            Q(p, 1) = st.invQ*Bq[1];
        }
        else if (apic && fittedBase && yRow < twoCells)
        {
            // Even APIC needs the quadratic mode in a fitted base's cell: the
            // affine field alone would carry to the base's nodes, which the base
            // condition resets, the curvature error of the velocity profile,
            // O(d^2 u''), a drag of rho c d per unit of it (c the elastic wave
            // speed) as large as the basal shear stress of a layer three cells
            // thick.
            if (st.quadratic)
            {
                for (int a = 0; a < 3; ++a)
                {
                    Pair rowQ = zero;
                    for (int b = 0; b < 3; ++b) rowQ += (wy[b]*st.q[b])*Pair::load(&vel(bx + a, by + b, 0));
                    Bq += wx[a]*rowQ;
                }
            }
            Q(p, 0) = st.invQ*Bq[0];
            Q(p, 1) = st.invQ*Bq[1];
        }
        L(p, 0) = L00*invD; L(p, 1) = L01*invD; L(p, 2) = Gx[1]*invD; L(p, 3) = L11*invD;
        v(p, 0) = vx;
        v(p, 1) = vy;
        if (average)
        {
            // Against volumetric locking (nu -> 0.5): the stress update takes the
            // volume-weighted mean dilatation of the particle's cell (B-bar), so the
            // incompressibility constraint is counted per cell, not per particle.
            auto acc = cellDilatation.access();
            acc(st.cellX(), st.cellY(), 0) += V(p)*(L00*invD + L11*invD);
            acc(st.cellX(), st.cellY(), 1) += V(p);
        }
        // Statistics of where the particles are going; they move in the stress pass,
        // after the nodal averaging has used the weights at the old positions.
        nx = x(p, 0) + dt*vx;
        ny = x(p, 1) + dt*vy - rows.height(nx);
        v2 = vx*vx + vy*vy;
    }

    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        for (int c = 0; c < nStats; ++c)
        {
            if (c == kinetic || c == momentumX) dst[c] += src[c];
            else if (src[c] > dst[c]) dst[c] = src[c];
        }
    }

    KOKKOS_INLINE_FUNCTION void init(value_type dst) const
    {
        for (int c = 0; c < nStats; ++c) dst[c] = (c == kinetic || c == momentumX || c == nonFinite || c == speed2) ? 0.0 : -1e300;
    }
};

StepStatistics toStatistics(const double* r)
{
    StepStatistics s;
    s.xmax = r[GridToParticle::xmax];
    s.xmin = -r[GridToParticle::negXmin];
    s.ymax = r[GridToParticle::ymax];
    s.ymin = -r[GridToParticle::negYmin];
    s.maxSpeed = std::sqrt(r[GridToParticle::speed2]);
    s.kineticEnergy = r[GridToParticle::kinetic];
    s.momentumX = r[GridToParticle::momentumX];
    s.finite = r[GridToParticle::nonFinite] == 0.0 && std::isfinite(s.xmax + s.xmin + s.ymax + s.ymin);
    return s;
}

} // namespace

TimeIntegrator::TimeIntegrator(const BaseFrame& frame, const UndrainedClay& clay, const BasalContact& contact,
                               const MpmControls& controls, const double density)
:
    frame_(frame), clay_(clay), contact_(contact), controls_(controls),
    splitting_{controls.particleSplitting, controls.maxParticleLength},
    density_(density),
    waveSpeed_(std::sqrt(clay.constrainedModulus()/density)),
    fittedBase_(controls.baseBoundary == MpmControls::BaseBoundary::fitted),
    blockSums_(controls.nodeSums == MpmControls::NodeSums::perBlock),
    rows_(gridRows(frame, controls))
{}

RowShear gridRows(const BaseFrame& frame, const MpmControls& controls)
{
    RowShear rows;
    rows.on = controls.baseBoundary == MpmControls::BaseBoundary::fitted && !frame.level.flat();
    if (rows.on) rows.base = frame.level;
    return rows;
}

double TimeIntegrator::stableTimeStep(const double cellSize, const double maxSpeed) const
{
    // Eq. (6), with the rows' spacing where sheared rows bring them closer than d.
    return controls_.courant*cellSize*rows_.minRowSpacing()/(waveSpeed_ + maxSpeed);
}

StepStatistics TimeIntegrator::statistics(const MaterialPoints& mp, const RowShear& rows)
{
    GridToParticle f;
    double r[GridToParticle::nStats];
    f.init(r);
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.position);
    auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.velocity);
    auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.mass);
    for (int p = 0; p < mp.count; ++p)
    {
        const double v2 = v(p, 0)*v(p, 0) + v(p, 1)*v(p, 1);
        r[GridToParticle::xmax] = std::max(r[GridToParticle::xmax], x(p, 0));
        r[GridToParticle::negXmin] = std::max(r[GridToParticle::negXmin], -x(p, 0));
        const double y = x(p, 1) - rows.height(x(p, 0));
        r[GridToParticle::ymax] = std::max(r[GridToParticle::ymax], y);
        r[GridToParticle::negYmin] = std::max(r[GridToParticle::negYmin], -y);
        r[GridToParticle::speed2] = std::max(r[GridToParticle::speed2], v2);
        r[GridToParticle::kinetic] += 0.5*m(p)*v2;
        r[GridToParticle::momentumX] += m(p)*v(p, 0);
        if (!std::isfinite(x(p, 0) + x(p, 1) + v2)) r[GridToParticle::nonFinite] = 1.0;
    }
    return toStatistics(r);
}

void TimeIntegrator::particleToGrid(const MaterialPoints& mp, BackgroundGrid& grid, const double dt) const
{
    // contribute() adds into the view (the duplicates on OpenMP, the view itself
    // with CUDA atomics): both are zeroed first.
    zeroInStream(grid.nodal);
    ParticleToGrid f;
    static_cast<TransferSetup&>(f) = TransferSetup(mp, grid, dt, controls_.transfer, fittedBase_);
    f.cellPressure = controls_.volumetricLocking == MpmControls::VolumetricLocking::cellAveraging;
    f.cellCapped = f.cellPressure && controls_.stressQuadrature == MpmControls::StressQuadrature::cellCapped;
    if (f.cellPressure && !grid.pressureSumsCurrent) averageCellPressure(mp, grid);
    f.scatter = grid.nodalScatter;
    f.avg = grid.pressureSums;
    f.sig = mp.stress;
    f.d = grid.d;
    f.gX = frame_.gravityX;
    f.gY = frame_.gravityY;
    f.fill = fittedBase_ && controls_.baseContact == MpmControls::BaseContact::touching;
    if (f.fill)
    {
        zeroInStream(grid.baseFill);
        grid.baseFillScatter.reset_except(grid.baseFill);
        f.baseFill = grid.baseFillScatter;
        f.size = mp.size;
    }
    f.scaleRowAbove = fittedBase_ && controls_.baseRowMassScaling;
    if (f.scaleRowAbove)
    {
        zeroInStream(grid.rowAboveBase);
        grid.rowAboveBaseScatter.reset_except(grid.rowAboveBase);
        f.rowAbove = grid.rowAboveBaseScatter;
        f.modulus = clay_.constrainedModulus();
    }
    if (blockSums_)
    {
        BlockParticleToGrid b;
        b.f = f;
        b.nodal = grid.nodal;
        b.count = mp.count;
        b.block = controls_.blockParticles;
        // 32 KB of scratch: room for a block whose particles run from the top of
        // one column of cells into the next (sorted by column, then row), on
        // grids up to 200 rows high; a wider block adds straight to the grid.
        b.capacity = 1024;
        // A thread per particle of a block on a GPU; on the host a block is
        // one thread's (the blocks are the parallel work there).
        using TeamPolicy = Kokkos::TeamPolicy<ExecutionSpace>;
        const TeamPolicy probe(1, 1);
        const int threads = std::min(b.block, probe.team_size_max(b, Kokkos::ParallelForTag()));
        TeamPolicy policy((mp.count + b.block - 1)/b.block, threads);
        Kokkos::parallel_for("particleToGridByBlocks",
                             policy.set_scratch_size(0, Kokkos::PerTeam(BlockParticleToGrid::scratchBytes(b.capacity))), b);
    }
    else
    {
        grid.nodalScatter.reset_except(grid.nodal);
        Kokkos::parallel_for("particleToGrid", Policy(0, mp.count), f);
        Kokkos::Experimental::contribute(grid.nodal, grid.nodalScatter);
    }
    if (f.fill) Kokkos::Experimental::contribute(grid.baseFill, grid.baseFillScatter);
    if (f.scaleRowAbove) Kokkos::Experimental::contribute(grid.rowAboveBase, grid.rowAboveBaseScatter);
}

void TimeIntegrator::averageCellPressure(const MaterialPoints& mp, BackgroundGrid& grid) const
{
    const auto sig = mp.stress;
    const auto V = mp.volume;
    sumOverCells(grid, mp.position, mp.count, KOKKOS_LAMBDA(const int p, double& a, double& b)
    {
        cellPressureTerms(sig, V, p, a, b);
    });
    Kokkos::deep_copy(ExecutionSpace(), grid.pressureSums, grid.averaging);
    cellMeans(grid.pressureSums);
    grid.pressureSumsCurrent = true;
}

StepStatistics TimeIntegrator::gridToParticle(MaterialPoints& mp, BackgroundGrid& grid, const double dt) const
{
    GridToParticle f;
    static_cast<TransferSetup&>(f) = TransferSetup(mp, grid, dt, controls_.transfer, fittedBase_);
    f.L = mp.velocityGradient;
    f.vel = grid.velocity;
    f.twoCells = 2.0*grid.d;
    f.average = controls_.volumetricLocking == MpmControls::VolumetricLocking::cellAveraging;
    if (f.average)
    {
        zeroInStream(grid.averaging);
        grid.averagingScatter.reset_except(grid.averaging);
        f.cellDilatation = grid.averagingScatter;
    }
    Kokkos::View<double*, Kokkos::HostSpace> r("stepStatistics", GridToParticle::nStats);
    f.count = mp.count;
    Kokkos::parallel_reduce("gridToParticle", Policy(0, (mp.count + particlesPerItem - 1)/particlesPerItem), f, r);
    if (f.average)
    {
        Kokkos::Experimental::contribute(grid.averaging, grid.averagingScatter);
        cellMeans(grid.averaging);
    }
    return toStatistics(r.data());
}

StepStatistics TimeIntegrator::step(MaterialPoints& mp, BackgroundGrid& grid, const double dt, const bool record,
                                    PhaseTimes* times) const
{
    particleToGrid(mp, grid, dt);
    if (times) times->lap(PhaseTimes::particleToGrid);
    const double boundaryWork = updateGrid(grid, dt);
    if (shifting()) shiftField(grid);
    if (times) times->lap(PhaseTimes::gridUpdate);
    StepStatistics s = gridToParticle(mp, grid, dt);
    s.boundaryWork = boundaryWork;
    if (times) times->lap(PhaseTimes::gridToParticle);
    updateStress(mp, grid, dt, record);
    if (times) times->lap(PhaseTimes::stressUpdate);
    return s;
}

void advanceTo(const TimeIntegrator& integrator, MaterialPoints& mp, BackgroundGrid& grid, double& t, const double T,
               StepStatistics& stats, double* boundaryWork, const std::function<void(double)>& afterStep)
{
    long long steps = 0;
    while (t < T - 1e-12*std::max(1.0, T))
    {
        if (!grid.fit(stats.xmin, stats.xmax, stats.ymin, stats.ymax, 8ull << 30))
        {
            throw std::runtime_error("advanceTo: the grid outgrew 8 GiB");
        }
        if (++steps % sortInterval == 0)
        {
            if (integrator.splitting().split(mp, grid, integrator.frame().level, 1ll << 30) < 0)
            {
                throw std::runtime_error("advanceTo: particle splitting would exceed 2^30 particles");
            }
            mp.sortByCell(grid);
        }
        const double dt = std::min(integrator.timeStep(grid.d, stats.maxSpeed), T - t);
        stats = integrator.step(mp, grid, dt);
        if (boundaryWork) *boundaryWork += stats.boundaryWork;
        t += dt;
        if (!stats.finite) throw std::runtime_error("advanceTo: non-finite particle state");
        if (afterStep) afterStep(t);
    }
}

} // namespace mpm
} // namespace slide
