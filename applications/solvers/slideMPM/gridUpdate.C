// The grid's update: the nodes' velocities from their momenta, the base's
// contact (BasalContact, on a base that cuts the grid or is a knot line of the
// B-splines), the rear wall, and the field particle shifting follows.
#include "timeIntegrator.H"

#include <algorithm>
#include <cmath>

namespace slide
{
namespace mpm
{

namespace
{

// The rear wall (normal to the frame's x axis) holds material back and lets it
// go: grid column i's nodes in rows [ja, jb) lose any upslope velocity.
KOKKOS_INLINE_FUNCTION void holdAtRearWall(const NodeField& vel, const int i, const int ja, const int jb)
{
    for (int j = ja; j < jb; ++j)
    {
        if (vel(i, j, 0) < 0.0) vel(i, j, 0) = 0.0;
    }
}

// Work the base and the rear wall did against grid column i's nodes in the step:
// their impulse m (v - v*) on each node (v* the velocity P2G's momentum gives,
// v the velocity they leave) times the velocity the node then moves with, as
// symplectic Euler moves it. A no-slip node is left at rest and takes no work,
// as a no-slip base in the continuum; a frictional one is worked by -s_b slip.
KOKKOS_INLINE_FUNCTION double columnBoundaryWork(const NodeField& nodal, const NodeField& vel, const int i,
                                                 const int ja, const int jb)
{
    double w = 0.0;
    for (int j = ja; j < jb; ++j)
    {
        const double m = nodal(i, j, BackgroundGrid::mass);
        if (!(m > 0.0)) continue;
        const double vx = vel(i, j, 0), vy = vel(i, j, 1);
        w += (m*vx - nodal(i, j, BackgroundGrid::momentumX))*vx + (m*vy - nodal(i, j, BackgroundGrid::momentumY))*vy;
    }
    return w;
}

// A node's excess fill for particle shifting (TimeIntegrator::shiftField):
// max(m/(fullMass a) - 1, 0), a the row's seededShare; 0 outside the storage
// and below the base's row.
struct ExcessFill
{
    NodeField nodal;
    int j0, ni, nj;
    double fullMass, shareBase, shareAbove;

    KOKKOS_INLINE_FUNCTION double operator()(const int i, const int j) const
    {
        if (i < 0 || i >= ni || j < 0 || j >= nj || j + j0 < -1) return 0.0;
        const int row = j + j0;
        const double share = row == -1 ? shareBase : row == 0 ? shareAbove : 1.0;
        const double e = nodal(i, j, BackgroundGrid::mass)/(fullMass*share) - 1.0;
        return e > 0.0 ? e : 0.0;
    }
};

} // namespace

double TimeIntegrator::updateGrid(BackgroundGrid& grid, const double dt) const
{
    if (fittedBase_) return updateGridFittedBase(grid, dt);
    const auto nodal = grid.nodal;
    const auto vel = grid.velocity;
    const double d = grid.d, xOrigin = grid.xOrigin;
    const int i0 = grid.i0, j0 = grid.j0, ja = grid.wj0 - grid.j0, jb = ja + grid.wnj;
    const BaseLevelSet level = frame_.level;
    const BasalContact contact = contact_;
    const bool noSlip = contact_.type == BasalContact::Type::noSlip;
    const double gSep = std::sqrt(frame_.gravityX*frame_.gravityX + frame_.gravityY*frame_.gravityY);
    const bool rearWall = frame_.rearWall;
    const double rearX = frame_.rearX;
    const int ia = grid.wi0 - grid.i0, ib = ia + grid.wni;
    double dissipated = 0.0;
    Kokkos::parallel_reduce("updateGrid", Policy(ia, ib), KOKKOS_LAMBDA(const int i, double& lost)
    {
        const double xi = xOrigin + (i0 + i)*d;
        const double yb = level.height(xi), slope = level.slope(xi);
        const double norm = std::sqrt(1.0 + slope*slope);
        const double tx = 1.0/norm, ty = slope/norm;

        int nc = 0;
        int row[BasalContact::maxNodes];
        double cm[BasalContact::maxNodes], cvx[BasalContact::maxNodes], cvy[BasalContact::maxNodes];
        double cvol[BasalContact::maxNodes], coff[BasalContact::maxNodes];
        for (int j = ja; j < jb; ++j)
        {
            const double m = nodal(i, j, BackgroundGrid::mass);
            double vx = 0.0, vy = 0.0;
            if (m > 0.0)
            {
                vx = nodal(i, j, BackgroundGrid::momentumX)/m;
                vy = nodal(i, j, BackgroundGrid::momentumY)/m;
            }
            const double offset = (yb - (j0 + j)*d)/d;   // how far the node lies below the base, in cells
            if (offset >= -1e-9 && offset < 1.5 && nc < BasalContact::maxNodes)
            {
                row[nc] = j;
                cm[nc] = m;
                cvx[nc] = vx;
                cvy[nc] = vy;
                cvol[nc] = nodal(i, j, BackgroundGrid::volume);
                coff[nc] = offset;
                ++nc;
            }
            else if (offset >= 1.5)
            {
                vx = 0.0;   // deep inside the base
                vy = 0.0;
            }
            vel(i, j, 0) = vx;
            vel(i, j, 1) = vy;
        }
        if (nc > 0)
        {
            const double fraction = BasalContact::contactFraction(nc, cvol, coff, d);
            contact.apply(nc, cm, cvx, cvy, tx, ty, d*norm, fraction, dt, gSep*dt);
            // No slip: the nodes below the base node take the velocity of their
            // mirror images above it, reversed, so that the B-splines interpolate
            // zero velocity on the base line (for a base on a grid line) instead of
            // letting the lowest material slip. (Frictional bases keep the contact
            // velocities, which carry the basal impulse exactly.)
            int kb = 0;
            for (int k = 1; k < nc; ++k) if (coff[k] < coff[kb]) kb = k;
            for (int k = 0; k < nc; ++k)
            {
                const int mirror = 2*row[kb] - row[k];
                if (noSlip && k != kb && cm[kb] > 0.0 && mirror >= ja && mirror < jb)
                {
                    cvx[k] = 2.0*cvx[kb] - vel(i, mirror, 0);
                    cvy[k] = 2.0*cvy[kb] - vel(i, mirror, 1);
                }
                vel(i, row[k], 0) = cvx[k];
                vel(i, row[k], 1) = cvy[k];
            }
        }
        if (rearWall && xi <= rearX + 1e-9*d) holdAtRearWall(vel, i, ja, jb);
        lost -= columnBoundaryWork(nodal, vel, i, ja, jb);
    }, dissipated);
    return dissipated;
}

double TimeIntegrator::updateGridFittedBase(BackgroundGrid& grid, const double dt) const
{
    const auto nodal = grid.nodal;
    const auto vel = grid.velocity;
    const double d = grid.d, xOrigin = grid.xOrigin;
    const int i0 = grid.i0, ja = grid.wj0 - grid.j0, jb = ja + grid.wnj;
    const int baseRow = -1 - grid.j0;   // storage row of the base's nodes (on y = 0)
    const BasalContact contact = contact_;
    const double gSep = std::sqrt(frame_.gravityX*frame_.gravityX + frame_.gravityY*frame_.gravityY);
    const bool rearWall = frame_.rearWall;
    const double rearX = frame_.rearX;
    // A slide covering a column's base gives its base node the volume d^2 (particleToGrid).
    const double fullVolume = d*d;
    const RowShear rows = grid.rows;
    const int ia = grid.wi0 - grid.i0, ib = ia + grid.wni;
    const bool touching = controls_.baseContact == MpmControls::BaseContact::touching;
    const auto fill = grid.baseFill;
    const bool scaleRowAbove = controls_.baseRowMassScaling;
    const auto above = grid.rowAboveBase;
    const int wnj = jb - ja;
    double dissipated = 0.0;
    // One thread per node: only the base's node (and a rear wall's column)
    // need more than the momentum over the mass, and a thread per column left
    // a GPU with a few hundred threads walking their columns.
    Kokkos::parallel_reduce("updateGrid", Policy(0, (ib - ia)*wnj), KOKKOS_LAMBDA(const int n, double& lost)
    {
        const int i = ia + n/wnj, j = ja + n%wnj;
        double m = nodal(i, j, BackgroundGrid::mass);
        double vx = 0.0, vy = 0.0;
        if (m > 0.0 && j >= baseRow)
        {
            vx = nodal(i, j, BackgroundGrid::momentumX)/m;
            vy = nodal(i, j, BackgroundGrid::momentumY)/m;
            if (scaleRowAbove && j == baseRow + 1)
            {
                // The internal force's impulse I moves the node as if its
                // mass were dt^2 K (its own frequency 1/dt, half the
                // central difference's limit) where its mass is less.
                const double scaled = dt*dt*above(i, 0);
                if (scaled > m)
                {
                    vx += above(i, 1)*(1.0/scaled - 1.0/m);
                    vy += above(i, 2)*(1.0/scaled - 1.0/m);
                }
            }
        }
        // The base's traction acts on the base's nodes alone: theirs are the
        // only functions that do not vanish on the base line.
        if (j == baseRow && m > 0.0 && (!touching || touchesBase(fill(i, 0), fill(i, 1))))
        {
            const double volume = nodal(i, j, BackgroundGrid::volume);
            const double fraction = volume < fullVolume ? volume/fullVolume : 1.0;
            double tx, ty, length;
            rows.columnTangent(xOrigin + (i0 + i)*d, d, tx, ty, length);
            contact.apply(1, &m, &vx, &vy, tx, ty, length, fraction, dt, gSep*dt);
        }
        // The rear wall holds material back and lets it go.
        const bool atRearWall = rearWall && xOrigin + (i0 + i)*d <= rearX + 1e-9*d;
        if (atRearWall && vx < 0.0) vx = 0.0;
        vel(i, j, 0) = vx;
        vel(i, j, 1) = vy;
        // Only the base's node and a rear wall's column change velocities: only
        // they are worked (columnBoundaryWork's terms, node by node).
        if ((atRearWall || j == baseRow) && m > 0.0)
        {
            lost -= (m*vx - nodal(i, j, BackgroundGrid::momentumX))*vx
                  + (m*vy - nodal(i, j, BackgroundGrid::momentumY))*vy;
        }
    }, dissipated);
    return dissipated;
}

double seededShare(const int row, const int particlesPerCell)
{
    if (row < -1) return 0.0;
    if (row > 0) return 1.0;
    const int n = particlesPerCell;
    double a = 0.0;
    for (int k = 0; k < n; ++k)
    {
        const double s = (k + 0.5)/n;   // in the base cell, and s + 1 in the cell above it
        a += (row == -1 ? (1.0 - s)*(1.0 - s) : 2.0*s - 1.5*s*s + 0.5*(1.0 - s)*(1.0 - s))/n;
    }
    return a;
}

void TimeIntegrator::shiftField(BackgroundGrid& grid) const
{
    // The nodes' excess fill e = max(m/(rho0 d^2 a) - 1, 0), a their
    // seededShare. Only overfull nodes push: a free surface's or a front's
    // nodes, part full, do not pull particles out.
    const double shareBase = seededShare(-1, controls_.particlesPerCell);
    const double shareAbove = seededShare(0, controls_.particlesPerCell);
    const auto nodal = grid.nodal;
    const auto S = grid.shift;
    const int j0 = grid.j0, ni = grid.ni, nj = grid.nj;
    const double fullMass = density_*grid.d*grid.d;
    const double k = controls_.particleShifting*grid.d;   // [m] per unit of excess per cell
    const RowShear rows = grid.rows;
    const double xOrigin = grid.xOrigin, d = grid.d;
    const int i0 = grid.i0;
    const ExcessFill excess{nodal, j0, ni, nj, fullMass, shareBase, shareAbove};
    Kokkos::parallel_for("shiftField", Policy(0, ni*nj), KOKKOS_LAMBDA(const int n)
    {
        const int i = n/nj, j = n - i*nj, row = j + j0;
        double gx = 0.0, gy = 0.0;
        if (row >= -1)
        {
            gx = 0.5*(excess(i + 1, j) - excess(i - 1, j));
            // Node rows at y = 0 (the base's), then (r + 1/2) d; the base's nodes
            // do not shift across it.
            if (row == 0) gy = (excess(i, j + 1) - excess(i, j - 1))/1.5;
            else if (row > 0) gy = 0.5*(excess(i, j + 1) - excess(i, j - 1));
            if (rows.on) gx -= rows.slope(xOrigin + (i0 + i)*d)*gy;
        }
        S(i, j, 0) = -k*gx;
        S(i, j, 1) = -k*gy;
    });
}

} // namespace mpm
} // namespace slide
