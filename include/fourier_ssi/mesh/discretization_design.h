/**
 * The discretization that Discretization/Target accuracy designs: a family
 * of nested FE_Q(4) meshes, member k = 0, 1, 2, ..., walked until the error
 * estimated from the members (sequence_error_estimate.h) is below the
 * target (doc/accuracy-vs-time.md, "Accuracy on demand").
 *
 * Member k is the scene's coarse mesh (Mesh subsection; its Global
 * refinements entry is replaced by k) with
 *  - k global refinements: every error source, the far field and the
 *    smooth parts included, falls with each member (a family graded only at
 *    the corners stalls at the error of its base mesh: 1e-5 on the
 *    embedded footing, so its differences under-report);
 *  - geometric grading toward every singular point found in the scene,
 *    first_grading_levels + grading_levels_per_member k bisections: the
 *    ends and corners of interface lines, the corners of material regions
 *    (rigid foundations, soil layers) and removed regions, and the edge of a
 *    surface patch. At an r^lambda corner singularity each bisection cuts
 *    the goal error by 2^-2lambda (0.41 rough, 0.63 smooth), for a constant
 *    number of cells per level; the end of a smooth interface (the slip
 *    wedge, 0.63 per bisection) gets slip_wedge_extra_levels more;
 *  - where a material has G ~ depth^alpha (alpha > 0), anisotropic layers
 *    under the ground surface, first_surface_layers + k cuts, since G
 *    vanishes at the surface.
 * The user's Point, Box and Layer refinement entries are applied as well
 * (expert overrides: a point given there takes the larger level count).
 */
#ifndef fourier_ssi_discretization_design_h
#define fourier_ssi_discretization_design_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/input/parameters.h>
#include <set>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  namespace DiscretizationDesign
  {
    /** Corner grading of member 0, and the levels added per member. */
    constexpr unsigned int first_grading_levels      = 8;
    constexpr unsigned int grading_levels_per_member = 2;
    /**
     * More bisections at the end of a smooth interface (ks = 0): its slip
     * wedge converges at 0.63 per bisection against 0.41 at a bonded
     * corner, and with the same levels it held the smooth embedded
     * footing's error at 3.6e-3 (K_M, member 0) where the rough one was at
     * 2e-5. Four more bring member 0 to 5.8e-4 for 7.4k more DoFs, so that
     * member 1 certifies 1e-3 (doc/accuracy-vs-time.md, "The slip wedge
     * graded deeper").
     */
    constexpr unsigned int slip_wedge_extra_levels = 4;
    /** Surface layers of member 0 (G ~ depth^alpha soil). */
    constexpr unsigned int first_surface_layers = 2;

    /**
     * The singular points of a built-in rectangle scene, inside the domain
     * (off the axis and off the far boundaries), each once. A gmsh mesh
     * has none (its points are not known here).
     */
    std::vector<Point<2>>
    singular_points(const MeshParameters &mesh);

    /**
     * The singular points (singular_points()) that end an interface line
     * whose law lets it slide freely (ks = 0: smooth, or tied in the normal
     * only): the slip wedges.
     */
    std::vector<Point<2>>
    slip_wedge_points(const AllParameters &parameters);

    /** The a priori refinements of member `member` (user's entries added). */
    AdaptivityParameters
    refinements(const AllParameters &parameters, const unsigned int member);

    /**
     * Build member `member` into `triangulation`: the scene's coarse mesh
     * refined `member` times globally, then refinements().
     */
    void
    build_member(const AllParameters                &parameters,
                 const unsigned int                  member,
                 const std::set<types::boundary_id> &interface_ids,
                 Triangulation<2>                   &triangulation);

    /**
     * Undo the last refinement of every cell whose siblings are all active
     * (the coarser nested member of a user's mesh: one level less of its
     * global refinements and of its grading). False if nothing can be
     * coarsened (a coarse mesh).
     */
    bool
    coarsen_once(Triangulation<2>                   &triangulation,
                 const std::set<types::boundary_id> &interface_ids);
    /**
     * A rectangle mesh of one cell in z and no global refinement: a slice
     * between smooth planes, whose fields do not vary in z (the plane-strain
     * pile and disc). Its members refine in r only.
     */
    bool
    is_one_cell_slice(const MeshParameters &mesh);

    /**
     * Member `member` of a plastic scene with a target
     * (doc/soil-plasticity.md section 8c): the scene's own mesh and element
     * with 2^member times the cells of each segment of a rectangle mesh,
     * each growth ratio raised to 2^-member (two fine cells fill one
     * coarse cell: nested, tools/capacity.py's family), in r, and in z
     * only where the scene has more than one cell in z (a one-cell slice
     * between smooth planes is exact in z). A gmsh mesh is refined
     * globally. Then the scene's a priori refinements.
     */
    void
    build_plastic_member(const AllParameters                &parameters,
                         const unsigned int                  member,
                         const std::set<types::boundary_id> &interface_ids,
                         Triangulation<2>                   &triangulation);
  } // namespace DiscretizationDesign
} // namespace FourierSSI

#endif
