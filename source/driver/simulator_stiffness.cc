// The Simulator's 6x6 foundation stiffness matrix (Rigid foundation/
// Stiffness matrix, doc/foundation-stiffness.md): the five terms of the
// harmonics' unit-load solves on the last mesh, with the error bars of
// their nested values, converted to SI and written for aeroelastic codes.
#include <cmath>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/postprocess/foundation_stiffness.h>
#include <limits>

namespace FourierSSI
{
  double
  Simulator::last_value(const std::string &quantity,
                        const Harmonic    &harmonic) const
  {
    for (unsigned int i = 0; i < outcomes.size(); ++i)
      {
        const Harmonic &h = harmonic_set->harmonic(i);
        if (h.n != harmonic.n || h.family != harmonic.family)
          continue;
        for (const HarmonicReport::Row &row : outcomes[i].report.rows)
          if (row.quantity == quantity)
            return row.value;
      }
    AssertThrow(false,
                ExcMessage("Rigid foundation/Stiffness matrix: no " + quantity +
                           " in harmonic " + harmonic.name()));
    return 0.;
  }

  double
  Simulator::estimated_error(const std::string &quantity,
                             const Harmonic    &harmonic) const
  {
    for (const GoalHistory &h : goal_histories)
      if (h.quantity == quantity && h.harmonic.n == harmonic.n &&
          h.harmonic.family == harmonic.family && h.values.size() >= 2)
        return estimate_sequence_error(h.values, assumed_ratio()).relative;
    return std::numeric_limits<double>::quiet_NaN();
  }

  void
  Simulator::report_foundation_stiffness(std::ostream &log)
  {
    const RigidFoundationParameters &f = parameters.rigid_foundation;
    if (!f.enabled || !f.stiffness_matrix)
      return;
    const Harmonic vertical{0, Family::symmetric};
    const Harmonic torsional{0, Family::antisymmetric};
    const Harmonic lateral{1, Family::symmetric};
    // The run works in kN and kPa; the matrix is in N (x 1e3). K_H, K_M and
    // K_MH are normalised by G a, G a^3 and G a^2 (thesis eq. 4.5).
    const double kN = 1e3, G = f.reference_shear_modulus,
                 a = f.reference_length;
    AxisymmetricStiffnessTerms t;
    t.vertical         = kN * last_value("K_V", vertical);
    t.torsional        = kN * last_value("K_T", torsional);
    t.horizontal       = kN * G * a * last_value("K_H", lateral);
    t.rocking          = kN * G * a * a * a * last_value("K_M", lateral);
    t.coupling         = kN * G * a * a * last_value("K_MH", lateral);
    t.vertical_error   = estimated_error("K_V", vertical);
    t.torsional_error  = estimated_error("K_T", torsional);
    t.horizontal_error = estimated_error("K_H", lateral);
    t.rocking_error    = estimated_error("K_M", lateral);
    t.coupling_error   = estimated_error("K_MH", lateral);
    const FoundationStiffness K =
      foundation_stiffness(t, f.reference_elevation);
    print_stiffness(K, log);
    if (!is_positive_definite(K.stiffness))
      log << "warning: the foundation stiffness matrix is not positive "
             "definite (K_MH^2 >= K_H K_M: check the mesh)"
          << std::endl;
    if (!writes_csv())
      return;
    const std::string csv = result_files.claim("foundation-stiffness.csv");
    write_stiffness_csv(K, csv);
    const std::string ssi =
      result_files.claim("foundation-stiffness-subdyn.txt");
    write_subdyn_ssi(K, ssi);
    log << "foundation stiffness written to " << csv << " and " << ssi
        << " (OpenFAST SubDyn SSI file)" << std::endl;
  }
} // namespace FourierSSI
