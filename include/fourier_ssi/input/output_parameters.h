/**
 * Subsection "Output" of the .prm file: where the results go, which files
 * are written (VTU, interface tractions, 3D lines and the revolved mesh),
 * the soil-reaction curves and the plastic field of plastic soil.
 */
#ifndef fourier_ssi_output_parameters_h
#define fourier_ssi_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <optional>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** A straight line in the (r, z) plane sampled at n_points points. */
  struct OutputLine
  {
    Point<2>     start, end;
    unsigned int n_points = 2;
  };

  struct OutputParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    std::string directory    = "output";
    std::string results_file = "results.csv";
    bool        write_vtu    = true;
    /** Stress amplitudes in the per-harmonic VTU. */
    bool write_stresses = true;
    /** Relative displacement and traction per interface node pair (CSV). */
    bool write_interface_tractions = true;
    /** 3D reconstruction along lines at the angles theta_degrees. */
    std::vector<OutputLine> lines;
    /**
     * Limit of Lines 3D points per line: a typo such as 1e8 points would
     * otherwise write gigabytes of CSV (each point is a search in the mesh
     * and one row per angle).
     */
    static constexpr unsigned int max_points_per_line = 100000;
    /**
     * Rows of lines-3d.csv (points times angles) at most: 2 lines of 1e5
     * points at 65 angles wrote 2.8 GB for a minute before this bound.
     */
    static constexpr std::size_t max_lines_3d_rows = 1000000;
    /** One line if Lines 3D and Theta values ask for more rows. */
    void
                        check_lines_3d_size() const;
    std::vector<double> theta_degrees;
    /** The mesh revolved about the axis with the 3D displacement. */
    bool         write_3d_vtu    = false;
    unsigned int theta_divisions = 36;
    /**
     * Soil-reaction curves (Soil reaction depths): the depths [m below
     * the pile's head], or, if soil_reaction_auto > 0, that many evenly
     * spaced; none if both are empty (doc/soil-reaction-curves.md).
     */
    std::vector<double> soil_reaction_depths;
    unsigned int        soil_reaction_auto = 0;

    bool
    soil_reaction_curves() const
    {
      return soil_reaction_auto > 0 || !soil_reaction_depths.empty();
    }

    /** Read the entry Soil reaction depths; one line if it is malformed. */
    void
    parse_soil_reaction_depths(const std::string &text);

    /**
     * Soil reaction pile: the pile's material id, or -1 (auto) for the
     * Rigid foundation's tied material (doc/soil-reaction-curves.md 8).
     */
    int soil_reaction_pile = -1;

    /** Read the entry Soil reaction pile; one line if it is malformed. */
    void
    parse_soil_reaction_pile(const std::string &text);

    /**
     * Plastic field steps: the load steps (numbered as in
     * load-displacement.csv, from 1) whose plastic field is written, in
     * increasing order; empty for `last` (the last converged step). Steps
     * beyond the path are known only at its end (checked there).
     */
    std::vector<unsigned int> plastic_field_steps;
    /** Plastic field planes: meridian angles [degrees], in [0, 360). */
    std::vector<double> plastic_field_planes = {0., 90.};
    /** Plastic field 3D: the revolved mesh with the plastic field. */
    bool plastic_field_3d = false;

    /** True if a plastic run writes any plastic-field file. */
    bool
    writes_plastic_field() const
    {
      return write_vtu && (!plastic_field_planes.empty() || plastic_field_3d);
    }

    /** Read the entry Plastic field steps; one line if it is malformed. */
    void
    parse_plastic_field_steps(const std::string &text);

    /**
     * Interface state 3D: the nonlinear interfaces' state as a surface
     * revolved about the axis (interface-state-3d-step<s>.vtu and
     * interface-state-3d.pvd) at the steps of Interface state steps (as
     * plastic_field_steps; empty for the last converged step).
     */
    bool                      interface_state_3d = false;
    std::vector<unsigned int> interface_state_steps;

    /** Read a list of load steps or 'last' of the entry `entry`. */
    static std::vector<unsigned int>
    parse_load_steps(const std::string &entry, const std::string &text);

    /** Read the entry Plastic field planes; one line if it is malformed. */
    void
    parse_plastic_field_planes(const std::string &text);

    /**
     * Only Output/Directory and Output/Results file of a parameter file,
     * read before (and whatever) the rest of the file is refused, by a
     * light scan of its lines that also reads files the parser refuses
     * (broken subsections, NUL bytes, UTF-16): every other entry is
     * skipped and no value is checked. Empty if the file cannot be read.
     */
    static std::optional<OutputParameters>
    read_folder_of(const std::string &prm_file);
  };
} // namespace FourierSSI

#endif
