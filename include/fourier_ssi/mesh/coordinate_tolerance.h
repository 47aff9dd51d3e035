/**
 * When two mesh points coincide. A tolerance relative to a length of the
 * mesh (a face, the smallest cell) alone fails in two ways, both met in
 * practice: a face graded 24 levels deep (5e-9 m at r = 1 m) has a
 * relative tolerance below one ulp of its own coordinates, and a domain of
 * 3e4 m places a vertex at r = 1 m only to about 3e4 ulp, far outside a
 * tolerance taken from the smallest cell. The coordinates of a vertex are
 * computed (grading, mapping from the unit cell) from numbers of up to the
 * mesh's extent, so their round-off is a few ulp of that extent.
 */
#ifndef fourier_ssi_coordinate_tolerance_h
#define fourier_ssi_coordinate_tolerance_h

#include <limits>

namespace FourierSSI
{
  /**
   * Coordinates computed from numbers of magnitude up to `scale` [m] agree
   * within this [m]: 64 ulp of the scale (of 1 m below it).
   */
  inline double
  coordinate_round_off(const double scale)
  {
    return 64. * std::numeric_limits<double>::epsilon() * (1. + scale);
  }

  /**
   * Two points a distance `length` [m] apart in the mesh's own terms (a face,
   * a cell) coincide within `relative` of it, but never closer than the
   * round-off of coordinates of magnitude `scale`.
   */
  inline double
  coincidence_tolerance(const double relative,
                        const double length,
                        const double scale)
  {
    return relative * length + coordinate_round_off(scale);
  }
} // namespace FourierSSI

#endif
