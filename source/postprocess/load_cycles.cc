#include <algorithm>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/postprocess/load_cycles.h>
#include <iomanip>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /** The index of the last point of segment `segment`. */
    unsigned int
    end_of_segment(const std::vector<CyclePoint> &path,
                   const unsigned int             segment)
    {
      unsigned int last = 0;
      for (unsigned int i = 0; i < path.size(); ++i)
        if (path[i].segment <= segment)
          last = i;
      return last;
    }

    /**
     * The closed integral of F du around the polygon of `points` (indices
     * into path), closed by the chord from the last back to the first:
     * the trapezoid rule.
     */
    double
    loop_area(const std::vector<CyclePoint>   &path,
              const std::vector<unsigned int> &points)
    {
      double work = 0.;
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const CyclePoint &a = path[points[k]];
          const CyclePoint &b = path[points[(k + 1) % points.size()]];
          work += 0.5 * (a.load + b.load) * (b.motion - a.motion);
        }
      return work;
    }

    /**
     * The points [start, end] of a cycle, every one (stride 1) or every
     * other one of each segment with its turning points kept (stride 2):
     * the same loop at twice the step.
     */
    std::vector<unsigned int>
    loop_points(const std::vector<CyclePoint> &path,
                const unsigned int             start,
                const unsigned int             end,
                const unsigned int             stride)
    {
      std::vector<unsigned int> points     = {start};
      unsigned int              since_turn = 0;
      for (unsigned int i = start + 1; i <= end; ++i)
        {
          ++since_turn;
          const bool turning =
            i == end || path[i + 1].segment != path[i].segment;
          if (turning || since_turn % stride == 0)
            points.push_back(i);
          if (turning)
            since_turn = 0;
        }
      return points;
    }

    RigidMotion
    interpolated(const RigidMotion &a, const RigidMotion &b, const double t)
    {
      RigidMotion m;
      m.horizontal_displacement =
        a.horizontal_displacement +
        t * (b.horizontal_displacement - a.horizontal_displacement);
      m.rotation = a.rotation + t * (b.rotation - a.rotation);
      m.vertical_displacement =
        a.vertical_displacement +
        t * (b.vertical_displacement - a.vertical_displacement);
      m.twist = a.twist + t * (b.twist - a.twist);
      return m;
    }

    /** Where F changes sign on [first, last], the last such place. */
    void
    find_zero_load(const std::vector<CyclePoint> &path,
                   const unsigned int             first,
                   const unsigned int             last,
                   LoadCycle                     &cycle)
    {
      for (unsigned int i = first; i < last; ++i)
        {
          const double a = path[i].load, b = path[i + 1].load;
          if (a == b || a * b > 0.)
            continue;
          cycle.passes_zero_load = true;
          cycle.at_zero_load =
            interpolated(path[i].rigid, path[i + 1].rigid, a / (a - b));
        }
    }

    LoadCycle
    cycle_of(const std::vector<CyclePoint> &path, const unsigned int j)
    {
      const unsigned int start    = end_of_segment(path, 2 * j - 1);
      const unsigned int reversal = end_of_segment(path, 2 * j);
      const unsigned int end      = end_of_segment(path, 2 * j + 1);
      const CyclePoint  &A = path[start], &B = path[reversal], &E = path[end];
      LoadCycle          cycle;
      cycle.end_load        = E.load;
      cycle.reversal_load   = B.load;
      cycle.end_motion      = E.motion;
      cycle.reversal_motion = B.motion;
      cycle.largest_load = cycle.smallest_load = A.load;
      for (unsigned int i = start; i <= end; ++i)
        {
          cycle.largest_load  = std::max(cycle.largest_load, path[i].load);
          cycle.smallest_load = std::min(cycle.smallest_load, path[i].load);
        }
      cycle.secant_stiffness = (E.load - B.load) / (E.motion - B.motion);
      // The polygon A -> B -> A' closed by the chord A' -> A; its error
      // from the steps by Richardson's rule for the trapezoid's h^2: the
      // same loop at twice the step differs by 3 times the error.
      cycle.dissipated_energy =
        loop_area(path, loop_points(path, start, end, 1));
      cycle.dissipated_energy_error =
        std::abs(cycle.dissipated_energy -
                 loop_area(path, loop_points(path, start, end, 2))) /
        3.;
      cycle.stored_energy = 0.5 * (0.5 * std::abs(E.load - B.load)) *
                            (0.5 * std::abs(E.motion - B.motion));
      const double four_pi_stored =
        4. * dealii::numbers::PI * cycle.stored_energy;
      cycle.damping_ratio = cycle.dissipated_energy / four_pi_stored;
      cycle.damping_ratio_error =
        cycle.dissipated_energy_error / four_pi_stored;
      find_zero_load(path, reversal, end, cycle);
      return cycle;
    }
  } // namespace

  std::vector<LoadCycle>
  load_cycles(const std::vector<CyclePoint> &path)
  {
    unsigned int segments = 0;
    for (const CyclePoint &p : path)
      segments = std::max(segments, p.segment);
    std::vector<LoadCycle> cycles;
    for (unsigned int j = 1; 2 * j + 1 <= segments; ++j)
      cycles.push_back(cycle_of(path, j));
    return cycles;
  }

  void
  write_load_cycles(std::ostream                 &out,
                    const std::vector<LoadCycle> &cycles,
                    const CycleQuantities        &names)
  {
    const std::string F = names.load + "_" + names.load_unit,
                      u = names.motion + "_" + names.motion_unit;
    out << "cycle,end_" << F << ",reversal_" << F << ",largest_" << F
        << ",smallest_" << F << ",end_" << u << ",reversal_" << u
        << ",secant_stiffness_" << names.load_unit << "_per_"
        << names.motion_unit
        << ",dissipated_energy_kJ,dissipated_energy_error_kJ,stored_energy_kJ,"
           "damping_ratio,damping_ratio_error,"
           "zero_load_vertical_m,zero_load_horizontal_m,"
           "zero_load_rotation_rad,zero_load_twist_rad\n";
    out << std::setprecision(10);
    for (unsigned int j = 0; j < cycles.size(); ++j)
      {
        const LoadCycle &c = cycles[j];
        out << j + 1 << ',' << c.end_load << ',' << c.reversal_load << ','
            << c.largest_load << ',' << c.smallest_load << ',' << c.end_motion
            << ',' << c.reversal_motion << ',' << c.secant_stiffness << ','
            << c.dissipated_energy << ',' << c.dissipated_energy_error << ','
            << c.stored_energy << ',' << c.damping_ratio << ','
            << c.damping_ratio_error;
        // No zero crossing (a one-way cycle about a mean): empty fields.
        if (c.passes_zero_load)
          out << ',' << c.at_zero_load.vertical_displacement << ','
              << c.at_zero_load.horizontal_displacement << ','
              << c.at_zero_load.rotation << ',' << c.at_zero_load.twist;
        else
          out << ",,,,";
        out << '\n';
      }
  }

  void
  log_load_cycles(std::ostream                 &log,
                  const std::vector<LoadCycle> &cycles,
                  const CycleQuantities        &names)
  {
    for (unsigned int j = 0; j < cycles.size(); ++j)
      {
        const LoadCycle   &c = cycles[j];
        std::ostringstream line;
        line << std::setprecision(4) << "cycle " << j + 1 << ": " << names.load
             << " " << c.reversal_load << " to " << c.end_load << " "
             << names.load_unit << " at " << names.motion << " "
             << c.reversal_motion << " to " << c.end_motion << " "
             << names.motion_unit << "; secant stiffness " << c.secant_stiffness
             << " " << names.load_unit << "/" << names.motion_unit
             << ", dissipated " << c.dissipated_energy << " +- "
             << c.dissipated_energy_error << " kJ, damping ratio "
             << c.damping_ratio << " +- " << c.damping_ratio_error
             << " (the steps' error)";
        if (c.passes_zero_load)
          line << "; at zero load: horizontal "
               << c.at_zero_load.horizontal_displacement << " m, rotation "
               << c.at_zero_load.rotation << " rad, vertical "
               << c.at_zero_load.vertical_displacement << " m, twist "
               << c.at_zero_load.twist << " rad";
        else
          line << "; the load does not pass zero";
        log << line.str() << '\n';
      }
  }
} // namespace FourierSSI
