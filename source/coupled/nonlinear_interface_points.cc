#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/initial_stress.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/fourier/harmonic_pair_integral.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Load path";

    /** Lagrange basis of the equidistant nodes k / p at xi. */
    std::vector<double>
    lagrange_values(const unsigned int p, const double xi)
    {
      std::vector<double> values(p + 1, 1.);
      for (unsigned int k = 0; k <= p; ++k)
        for (unsigned int m = 0; m <= p; ++m)
          if (m != k)
            values[k] *= (xi - double(m) / p) / (double(k) - double(m)) * p;
      return values;
    }

    const std::vector<InterfacePair> &
    pairs_of(const HarmonicProblem &problem)
    {
      AssertThrow(problem.get_interfaces() != nullptr,
                  ExcMessage(entry + ": the scene has no interfaces"));
      return problem.get_interfaces()->get_pairs();
    }

    /**
     * 1/r - 1/k per component, r the springs of the return mapping (those
     * in K), k the law's own (infinite for exact contact): an augmented
     * sample's origin is p_c - (lambda - t0) times it, so that where lambda
     * = t the return from it gives t - t0 = k (d - p), the law's own (p its
     * slip; doc/nonlinear-interfaces.md section 5d); 0 where k is K's
     * spring.
     */
    LocalVector
    augmented_flexibility(const LocalVector &r,
                          const LocalVector &k,
                          const bool         exact)
    {
      LocalVector a = {{0., 0., 0.}};
      for (unsigned int c = 0; c < 3; ++c)
        if (exact)
          a[c] = 1. / r[c];
        else if (k[c] != r[c])
          a[c] = 1. / r[c] - 1. / k[c];
      return a;
    }

    ThetaFactor
    factor_of(const unsigned int c)
    {
      return c == 2 ? ThetaFactor::circumferential : ThetaFactor::in_plane;
    }
  } // namespace

  NonlinearInterfacePoints::NonlinearInterfacePoints(
    const HarmonicSet   &set,
    const AllParameters &parameters,
    const bool           augment_stiff_laws)
    : set(set)
  {
    const std::vector<InterfacePair> &pairs = pairs_of(set.problem(0));
    const InterfaceIntegrator &integrator   = *set.problem(0).get_interfaces();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const InterfaceLaw &law =
          parameters.interfaces.laws.at(pairs[i].boundary_id);
        if (!law.is_nonlinear())
          continue;
        // One law per pair: its springs are resolved per face (contact's
        // augmentation, G / l), and K may hold softer ones (Newton's cap).
        const InterfaceStiffness &spring    = integrator.get_law_stiffness()[i];
        const InterfaceStiffness &in_K      = integrator.get_stiffness()[i];
        const unsigned int        law_index = laws.size();
        const LocalVector law_k = {{spring.shear, spring.normal, spring.shear}};
        const LocalVector K_k   = {{in_K.shear, in_K.normal, in_K.shear}};
        // A coulomb law stiffer than K (Newton's cap) is solved by the
        // augmented Lagrangian on K's springs with its own compliance
        // (augmented_flexibility), as contact is with none.
        const bool augmented = augments(law, spring, in_K, augment_stiff_laws);
        laws.emplace_back(law,
                          augmented ? in_K.normal : spring.normal,
                          augmented ? in_K.shear : spring.shear);
        stiffness.push_back(K_k);
        const bool is_contact = law.kind == InterfaceLaw::Kind::contact;
        contact.push_back(is_contact);
        law_springs.push_back(law_k);
        flexibility.push_back(augmented ?
                                augmented_flexibility(K_k, law_k, is_contact) :
                                LocalVector{{0., 0., 0.}});
        soil_scale.push_back(integrator.get_soil_scale()[i]);
        if (law.cohesion == 0. && !parameters.initial_stress.enabled())
          strengthless = true;
        nonlinear_pairs.push_back(i);
        const unsigned int p = pairs[i].nodes.size() - 1;
        // The rule K's matrix of this interface was integrated with, so a
        // sticking interface gives exactly no correction.
        const Quadrature<1> rule =
          nonlinear_interface_rule(p, parameters.interfaces.nodal_integration);
        // The face is straight (equidistant nodes on a line): the share of
        // point q runs between the rule's cumulative weights before and
        // after it, in order along the face (deal.II's rules are sorted).
        const Point<2> &first = pairs[i].nodes.front(),
                       &last  = pairs[i].nodes.back();
        double weight_before  = 0.;
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            InterfacePoint point;
            point.pair  = i;
            point.law   = law_index;
            point.share = {
              {first + weight_before * (last - first),
               first + (weight_before + rule.weight(q)) * (last - first)}};
            weight_before += rule.weight(q);
            point.shape = lagrange_values(p, rule.point(q)[0]);
            for (unsigned int k = 0; k <= p; ++k)
              for (unsigned int d = 0; d < 2; ++d)
                point.position[d] += point.shape[k] * pairs[i].nodes[k][d];
            point.area_per_radian =
              rule.weight(q) * pairs[i].length * point.position[0];
            point.initial_traction =
              initial_interface_traction(parameters.initial_stress,
                                         pairs[i].tangent,
                                         pairs[i].normal,
                                         parameters.materials.depth(
                                           point.position[1]));
            points.push_back(point);
          }
      }
    AssertThrow(!points.empty(),
                ExcMessage(entry + ": no face of a coulomb interface"));
  }

  bool
  NonlinearInterfacePoints::augments(const InterfaceLaw       &law,
                                     const InterfaceStiffness &own,
                                     const InterfaceStiffness &in_K,
                                     const bool augment_stiff_laws)
  {
    return law.kind == InterfaceLaw::Kind::contact ||
           (augment_stiff_laws &&
            (own.normal != in_K.normal || own.shear != in_K.shear));
  }

  const InterfacePair &
  NonlinearInterfacePoints::pair_of(const InterfacePoint &point) const
  {
    return pairs_of(set.problem(0))[point.pair];
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::relative_displacements(
    const std::vector<Vector<double>> &fields,
    const ThetaSampling               &sampling) const
  {
    std::vector<double> amplitudes = owned_amplitudes(fields);
    // Every harmonic's amplitudes on every rank: each entry is non-zero on
    // its owner only, so the sum is exact and the same bits on every rank,
    // whatever the reduction order.
    set.sum_over_ranks(amplitudes);
    return sampled(amplitudes, sampling);
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::owned_relative_displacements(
    const std::vector<Vector<double>> &fields,
    const ThetaSampling               &sampling) const
  {
    return sampled(owned_amplitudes(fields), sampling);
  }

  std::vector<double>
  NonlinearInterfacePoints::owned_amplitudes(
    const std::vector<Vector<double>> &fields) const
  {
    // The amplitudes of (d_s, d_n, d_theta) at every point, index
    // (i * 3 + c) * H + h, of the harmonics this rank owns (zero for the
    // others).
    const unsigned int  H = set.size();
    std::vector<double> amplitudes(points.size() * 3 * H, 0.);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const InterfacePoint &point        = points[i];
        double *const         amplitude[3] = {&amplitudes[(i * 3 + 0) * H],
                                              &amplitudes[(i * 3 + 1) * H],
                                              &amplitudes[(i * 3 + 2) * H]};
        for (unsigned int h = 0; h < H; ++h)
          {
            if (!set.owns(h))
              continue;
            const InterfacePair &pair    = pairs_of(set.problem(h))[point.pair];
            const unsigned int   n_nodes = pair.nodes.size();
            for (unsigned int k = 0; k < n_nodes; ++k)
              {
                double jump[3];
                for (unsigned int c = 0; c < 3; ++c)
                  jump[c] = fields[h](pair.dof_indices[3 * (n_nodes + k) + c]) -
                            fields[h](pair.dof_indices[3 * k + c]);
                const double N_k = point.shape[k];
                amplitude[0][h] +=
                  N_k * (jump[0] * pair.tangent[0] + jump[1] * pair.tangent[1]);
                amplitude[1][h] +=
                  N_k * (jump[0] * pair.normal[0] + jump[1] * pair.normal[1]);
                amplitude[2][h] += N_k * jump[2];
              }
          }
      }
    return amplitudes;
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::sampled(const std::vector<double> &amplitudes,
                                    const ThetaSampling       &sampling) const
  {
    // The samples at every theta_j, summed over the harmonics.
    const unsigned int       N = sampling.n_samples(), H = set.size();
    std::vector<LocalVector> result(points.size() * N, {{0., 0., 0.}});
    std::vector<double>      amplitude(H), samples;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::copy(amplitudes.begin() + (i * 3 + c) * H,
                    amplitudes.begin() + (i * 3 + c + 1) * H,
                    amplitude.begin());
          sampling.evaluate(amplitude, factor_of(c), samples);
          for (unsigned int j = 0; j < N; ++j)
            result[i * N + j][c] = samples[j];
        }
    return result;
  }

  void
  NonlinearInterfacePoints::for_each_return(
    const std::vector<LocalVector>                         &relative,
    const std::vector<LocalVector>                         &committed_plastic,
    const std::function<void(const unsigned int,
                             const unsigned int,
                             const ReturnMappingResult &)> &use) const
  {
    const unsigned int N = relative.size() / std::max<size_t>(size(), 1);
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        {
          const unsigned int k = i * N + j;
          use(k,
              i,
              laws[points[i].law].return_map(relative[k],
                                             points[i].initial_traction,
                                             committed_plastic[k]));
        }
  }

  InterfaceLoadCases
  NonlinearInterfacePoints::load_cases(const LoadPattern   &loads,
                                       const ThetaSampling &sampling) const
  {
    InterfaceLoadCases cases;
    cases.pattern = relative_displacements(loads.solution, sampling);
    if (!loads.held_solution.empty())
      cases.held = relative_displacements(loads.held_solution, sampling);
    if (!loads.swipe_solution.empty())
      cases.swipe = relative_displacements(loads.swipe_solution, sampling);
    return cases;
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::iterate_relative(
    const std::vector<Vector<double>> &correction,
    const ThetaSampling               &sampling,
    const InterfaceLoadCases          &cases,
    const double                       load_factor,
    const double                       held_fraction,
    const double                       swipe_force) const
  {
    std::vector<LocalVector> relative =
      relative_displacements(correction, sampling);
    const std::array<std::pair<double, const std::vector<LocalVector> *>, 3>
      terms = {{{load_factor, &cases.pattern},
                {held_fraction, &cases.held},
                {swipe_force, &cases.swipe}}};
    // The loads' part is summed first, then added to the correction's.
    for (unsigned int k = 0; k < relative.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        {
          double loads = 0.;
          for (const auto &[factor, samples] : terms)
            if (!samples->empty())
              loads += factor * (*samples)[k][c];
          relative[k][c] += loads;
        }
    return relative;
  }

  ContactCounts
  NonlinearInterfacePoints::return_map(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &committed_plastic,
    std::vector<LocalVector>       &plastic,
    std::vector<LocalVector>       &traction,
    std::vector<ContactState>      &state) const
  {
    ContactCounts counts = {{0, 0, 0}};
    plastic.resize(relative.size());
    traction.resize(relative.size());
    state.resize(relative.size());
    for_each_return(relative,
                    committed_plastic,
                    [&](const unsigned int k,
                        const unsigned int /*point*/,
                        const ReturnMappingResult &r) {
                      plastic[k]  = r.plastic;
                      traction[k] = r.traction;
                      state[k]    = r.state;
                      ++counts[static_cast<int>(r.state)];
                    });
    return counts;
  }

  std::vector<LocalTangent>
  NonlinearInterfacePoints::plastic_tangents(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &committed_plastic) const
  {
    std::vector<LocalTangent> result(relative.size());
    for_each_return(relative,
                    committed_plastic,
                    [&](const unsigned int         k,
                        const unsigned int         i,
                        const ReturnMappingResult &r) {
                      // d_p = d - D^-1 (t - t0 - D d_p,old):
                      // dd_p = (I - D^-1 D_t) dd.
                      for (unsigned int a = 0; a < 3; ++a)
                        for (unsigned int b = 0; b < 3; ++b)
                          result[k][a * 3 + b] =
                            (a == b ? 1. : 0.) -
                            r.tangent[a * 3 + b] / stiffness[points[i].law][a];
                    });
    return result;
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::iteration_plastic(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &traction,
    const std::vector<LocalVector> &plastic) const
  {
    const unsigned int       N = relative.size() / std::max<size_t>(size(), 1);
    std::vector<LocalVector> result = plastic;
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const unsigned int law = points[i].law;
        if (augmented(law) || stiffness[law] == law_springs[law])
          continue;
        for (unsigned int j = 0; j < N; ++j)
          for (unsigned int c = 0; c < 3; ++c)
            {
              const unsigned int k = i * N + j;
              result[k][c]         = relative[k][c] -
                             (traction[k][c] - points[i].initial_traction[c]) /
                               stiffness[law][c];
            }
      }
    return result;
  }

  void
  NonlinearInterfacePoints::describe(std::ostream      &log,
                                     const unsigned int n_samples,
                                     const unsigned int highest_harmonic) const
  {
    // Per boundary id: contact or not, and the smallest kn l / G of its
    // faces (the largest compliance error).
    struct Springs
    {
      bool   contact   = false;
      bool   augmented = false;
      double smallest  = std::numeric_limits<double>::max();
    };
    std::map<types::boundary_id, Springs> by_id;
    for (const InterfacePoint &point : points)
      {
        Springs &springs  = by_id[pair_of(point).boundary_id];
        springs.contact   = contact[point.law];
        springs.augmented = springs.augmented || augmented(point.law);
        springs.smallest =
          std::min(springs.smallest,
                   law_springs[point.law][1] / soil_scale[point.law]);
      }
    const unsigned int needed = 2 * highest_harmonic + 1;
    for (const auto &[id, springs] : by_id)
      {
        log << "interface " << id << ": ";
        if (springs.contact)
          log << "contact, exact non-penetration (augmented Lagrangian, "
                 "augmentation "
              << springs.smallest << " G/l)";
        else
          log << "coulomb, kn >= " << springs.smallest
              << " G/l (G of the softer side, l the mean face length): "
                 "compliance error against rigid contact about "
              << compliance_error_coefficient << " G/(kn r0) <= "
              << compliance_error_coefficient / springs.smallest
              << " for a foundation of size r0 >= l"
              << (springs.augmented ?
                    " (springs stiffer than K's: solved by the augmented "
                    "Lagrangian on K's)" :
                    "");
        log << "; " << n_samples
            << " theta samples for n <= " << highest_harmonic
            << " (2 n_max + 1 = " << needed << " carry the band-limited gap"
            << (n_samples > needed ? ", more over-constrain a stiff penalty" :
                                     "")
            << ")\n";
      }
  }

  bool
  NonlinearInterfacePoints::any_augmented() const
  {
    for (unsigned int law = 0; law < laws.size(); ++law)
      if (augmented(law))
        return true;
    return false;
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::update_multipliers(
    const std::vector<LocalVector> &traction,
    const std::vector<LocalVector> &slip,
    std::vector<LocalVector>       &origin) const
  {
    const unsigned int       N = traction.size() / std::max<size_t>(size(), 1);
    std::vector<LocalVector> change(origin.size(), LocalVector{{0., 0., 0.}});
    for (unsigned int i = 0; i < points.size(); ++i)
      if (augmented(points[i].law))
        for (unsigned int j = 0; j < N; ++j)
          for (unsigned int c = 0; c < 3; ++c)
            {
              // The origin p_c - a (lambda - t0) (a = augmented_flexibility,
              // 1 / r for contact); lambda <- t moves it by a (lambda - t):
              // for contact the penetration (c = n) or elastic slip the
              // spring r allowed, for a stiff coulomb law the part of it
              // its own k would not have allowed.
              const unsigned int k  = i * N + j;
              const double       a  = flexibility[points[i].law][c];
              const double       t0 = points[i].initial_traction[c];
              change[k][c] =
                slip[k][c] - origin[k][c] - a * (traction[k][c] - t0);
              origin[k][c] += change[k][c];
            }
    return change;
  }

  std::vector<LocalVector>
  NonlinearInterfacePoints::spring_plastic(const InterfaceSnapshot &state) const
  {
    const unsigned int N = state.relative.size() / std::max<size_t>(size(), 1);
    std::vector<LocalVector> plastic(state.relative.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        for (unsigned int c = 0; c < 3; ++c)
          {
            const unsigned int k = i * N + j;
            plastic[k][c] =
              state.relative[k][c] -
              (state.traction[k][c] - points[i].initial_traction[c]) /
                stiffness[points[i].law][c];
          }
    return plastic;
  }

  NonlinearInterfacePoints::MultiplierUpdate
  NonlinearInterfacePoints::update_and_test_multipliers(
    const std::vector<LocalVector> &traction,
    const std::vector<LocalVector> &slip,
    const ThetaSampling            &sampling,
    std::vector<LocalVector>       &origin,
    const double                    allowed_force,
    const unsigned int              update) const
  {
    const std::vector<LocalVector> change =
      update_multipliers(traction, slip, origin);
    // The change of the multipliers acts on the displacements only through
    // its nodal force (the origin's change is a plastic part, load_of).
    if (norm_over_harmonics(load_of(change, sampling)) <= allowed_force)
      return MultiplierUpdate::converged;
    return update == maximum_multiplier_updates ? MultiplierUpdate::too_many :
                                                  MultiplierUpdate::again;
  }

  InterfaceState
  NonlinearInterfacePoints::at_rest(const ThetaSampling &sampling) const
  {
    InterfaceState state;
    state.plastic.assign(size() * sampling.n_samples(), {{0., 0., 0.}});
    state.origin = state.plastic;
    state.slip   = state.plastic;
    return state;
  }

  void
  NonlinearInterfacePoints::commit(const std::vector<LocalVector> &relative,
                                   const std::vector<LocalVector> &traction,
                                   std::vector<LocalVector>      &&plastic,
                                   InterfaceState                 &state) const
  {
    state.plastic        = std::move(plastic);
    const unsigned int N = relative.size() / std::max<size_t>(size(), 1);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const unsigned int law = points[i].law;
        if (!augmented(law))
          continue;
        for (unsigned int j = 0; j < N; ++j)
          {
            // Exact contact keeps no elastic slip: the tangential relative
            // displacement is all slip; the gap is no memory (its normal
            // part 0). A stiff coulomb law keeps its own elastic part,
            // p = d - (t - t0) / k, as its return mapping does. The next
            // step starts from lambda = t.
            const unsigned int k    = i * N + j;
            const LocalVector &t0   = points[i].initial_traction;
            LocalVector       &slip = state.slip[k];
            for (unsigned int c = 0; c < 3; ++c)
              slip[c] = contact[law] ?
                          (c == 1 ? 0. : relative[k][c]) :
                          relative[k][c] -
                            (traction[k][c] - t0[c]) / law_springs[law][c];
            for (unsigned int c = 0; c < 3; ++c)
              state.plastic[k][c] =
                slip[c] - flexibility[law][c] * (traction[k][c] - t0[c]);
          }
      }
    state.origin = state.plastic;
  }

  double
  NonlinearInterfacePoints::largest_yield_value(
    const std::vector<LocalVector> &traction) const
  {
    const unsigned int N       = traction.size() / std::max<size_t>(size(), 1);
    double             largest = -std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        largest =
          std::max(largest,
                   laws[points[i].law].yield_function(traction[i * N + j]));
    return largest;
  }

  double
  NonlinearInterfacePoints::largest_penetration(
    const std::vector<LocalVector> &relative) const
  {
    const unsigned int N = relative.size() / std::max<size_t>(size(), 1);
    double             penetration = 0., largest = 0.;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int j = 0; j < N; ++j)
        {
          const LocalVector &d = relative[i * N + j];
          for (const double v : d)
            largest = std::max(largest, std::abs(v));
          if (contact[points[i].law])
            penetration = std::max(penetration, -d[1]);
        }
    return largest > 0. ? penetration / largest : 0.;
  }

  void
  NonlinearInterfacePoints::write_multiplier_updates(
    std::ostream                   &log,
    const unsigned int              updates,
    const std::vector<LocalVector> &relative) const
  {
    if (updates == 0)
      return;
    // Only exact contact has a penetration to report; a stiff coulomb law's
    // is its own compliance.
    if (std::find(contact.begin(), contact.end(), true) == contact.end())
      log << "; " << updates << " multiplier updates";
    else
      log << "; " << updates << " contact multiplier updates, penetration "
          << largest_penetration(relative)
          << " of the largest relative displacement";
  }

  std::vector<Vector<double>>
  NonlinearInterfacePoints::load_of(const std::vector<LocalVector> &plastic,
                                    const ThetaSampling            &sampling,
                                    const bool condensed) const
  {
    const unsigned int          N = sampling.n_samples(), H = set.size();
    std::vector<Vector<double>> load(H);
    for (unsigned int h = 0; h < H; ++h)
      load[h].reinit(set.problem(h).get_dof_handler().n_dofs());
    std::vector<double> samples(N), coefficient[3];
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const InterfacePoint &point = points[i];
        bool                  any   = false;
        for (unsigned int c = 0; c < 3; ++c)
          {
            for (unsigned int j = 0; j < N; ++j)
              {
                samples[j] = stiffness[point.law][c] * plastic[i * N + j][c];
                any        = any || samples[j] != 0.;
              }
            // The theta part of the virtual work against each harmonic.
            sampling.integrate(samples, factor_of(c), coefficient[c]);
          }
        if (!any)
          continue;
        for (unsigned int h = 0; h < H; ++h)
          {
            const InterfacePair &pair    = pairs_of(set.problem(h))[point.pair];
            const unsigned int   n_nodes = pair.nodes.size();
            Vector<double>       local(pair.dof_indices.size());
            for (unsigned int k = 0; k < n_nodes; ++k)
              {
                // B^T: local (s, n, theta) forces rotated back to (r, z,
                // theta) (eq. 3.13, T^T), + on face B and - on face A.
                const double w    = point.area_per_radian * point.shape[k];
                const double f_s  = w * coefficient[0][h],
                             f_n  = w * coefficient[1][h],
                             f_t  = w * coefficient[2][h];
                const double f[3] = {f_s * pair.tangent[0] +
                                       f_n * pair.normal[0],
                                     f_s * pair.tangent[1] +
                                       f_n * pair.normal[1],
                                     f_t};
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    local(3 * (n_nodes + k) + c) += f[c];
                    local(3 * k + c) -= f[c];
                  }
              }
            if (condensed)
              set.problem(h)
                .get_homogeneous_constraints()
                .distribute_local_to_global(local, pair.dof_indices, load[h]);
            else
              for (unsigned int d = 0; d < local.size(); ++d)
                load[h](pair.dof_indices[d]) += local(d);
          }
      }
    return load;
  }

  void
  NonlinearInterfacePoints::write_state_csv(
    const std::string                    &filename,
    const std::vector<InterfaceSnapshot> &snapshots,
    const ThetaSampling                  &sampling) const
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    // t_n > 0 is tension, d_n > 0 opening (section 1 of the doc); the
    // traction is the total one, initial (geostatic) stress included.
    out << "step,interface_id,point,r_m,z_m,normal_r,normal_z,theta_deg,"
           "state,t_s_kPa,t_n_kPa,t_theta_kPa,d_s_m,d_n_m,d_theta_m\n"
        << std::setprecision(10);
    const std::vector<InterfacePair> &pairs = pairs_of(set.problem(0));
    const unsigned int                N     = sampling.n_samples();
    for (unsigned int s = 0; s < snapshots.size(); ++s)
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const InterfacePair &pair = pairs[points[i].pair];
          for (unsigned int j = 0; j < N; ++j)
            {
              const unsigned int k = i * N + j;
              const LocalVector &t = snapshots[s].traction[k];
              const LocalVector &d = snapshots[s].relative[k];
              out << s + 1 << ',' << pair.boundary_id << ',' << i << ','
                  << points[i].position[0] << ',' << points[i].position[1]
                  << ',' << pair.normal[0] << ',' << pair.normal[1] << ','
                  << sampling.angle(j) * 180. / numbers::PI << ','
                  << to_string(snapshots[s].state[k]) << ',' << t[0] << ','
                  << t[1] << ',' << t[2] << ',' << d[0] << ',' << d[1] << ','
                  << d[2] << '\n';
            }
        }
    file.commit();
  }

  std::vector<std::vector<std::vector<types::global_dof_index>>>
  NonlinearInterfacePoints::pair_dofs() const
  {
    std::vector<std::vector<std::vector<types::global_dof_index>>> dofs;
    for (const unsigned int i : nonlinear_pairs)
      {
        dofs.emplace_back();
        for (unsigned int h = 0; h < set.size(); ++h)
          dofs.back().push_back(pairs_of(set.problem(h))[i].dof_indices);
      }
    return dofs;
  }

  bool
  NonlinearInterfacePoints::softening_at(const InterfacePoint &point,
                                         const LocalVector    &relative,
                                         const LocalVector &committed_plastic,
                                         std::array<double, 9> &softening) const
  {
    const MohrCoulombInterface &law = laws[point.law];
    const ReturnMappingResult   at =
      law.return_map(relative, point.initial_traction, committed_plastic);
    if (at.state == ContactState::stick)
      return false;
    // The closed-form consistent tangent of the return (interface_law.h):
    // exact in every regime, so Newton converges quadratically once the
    // states settle.
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        softening[a * 3 + b] =
          (a == b ? stiffness[point.law][a] : 0.) - at.tangent[a * 3 + b];
    return true;
  }

  void
  NonlinearInterfacePoints::relative_displacement_operator(
    const InterfacePoint &point,
    const InterfacePair  &pair,
    FullMatrix<double>   &B) const
  {
    const unsigned int n_nodes = pair.nodes.size();
    B.reinit(3, pair.dof_indices.size());
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        const double N_k = point.shape[k];
        // d = sum_k N_k (u_B,k - u_A,k) rotated to (s, n, theta).
        const double rows[3][3] = {{pair.tangent[0], pair.tangent[1], 0.},
                                   {pair.normal[0], pair.normal[1], 0.},
                                   {0., 0., 1.}};
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            {
              B(a, 3 * (n_nodes + k) + c) += N_k * rows[a][c];
              B(a, 3 * k + c) -= N_k * rows[a][c];
            }
      }
  }

  unsigned int
  NonlinearInterfacePoints::add_softening(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &committed_plastic,
    const ThetaSampling            &sampling,
    CoupledTangent                 &tangent) const
  {
    const unsigned int    N = sampling.n_samples(), H = set.size(), HH = H * H;
    HarmonicPairIntegral  integral(set.get_harmonics(), sampling, 3, 2);
    std::array<double, 9> c;
    std::vector<double>   S;
    FullMatrix<double>    B, local;
    unsigned int          n_softening = 0;
    for (const InterfacePoint &point : points)
      {
        const unsigned int i       = &point - points.data();
        bool               softens = false;
        for (unsigned int j = 0; j < N; ++j)
          {
            if (!softening_at(
                  point, relative[i * N + j], committed_plastic[i * N + j], c))
              continue;
            if (!softens)
              integral.clear();
            softens = true;
            ++n_softening;
            integral.add_sample(j, c.data());
          }
        if (!softens)
          continue;
        integral.integrals(S);
        // B is the same for every harmonic (the theta factors are in S);
        // only the DoF numbers differ.
        relative_displacement_operator(point, pair_of(point), B);
        const unsigned int n_dofs = B.n();
        local.reinit(n_dofs, n_dofs);
        for (unsigned int h = 0; h < H; ++h)
          for (unsigned int g = 0; g < H; ++g)
            {
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  {
                    const double s =
                      point.area_per_radian * S[(a * 3 + b) * HH + h * H + g];
                    if (s == 0.)
                      continue;
                    for (unsigned int x = 0; x < n_dofs; ++x)
                      if (B(a, x) != 0.)
                        for (unsigned int y = 0; y < n_dofs; ++y)
                          local(x, y) -= B(a, x) * s * B(b, y);
                  }
              tangent.add(h,
                          g,
                          local,
                          pairs_of(set.problem(h))[point.pair].dof_indices,
                          pairs_of(set.problem(g))[point.pair].dof_indices);
              local = 0.;
            }
      }
    return n_softening;
  }

  std::array<double, 6>
  NonlinearInterfacePoints::foundation_resultant(
    const std::vector<LocalVector>  &traction,
    const ThetaSampling             &sampling,
    const RigidFoundationParameters &foundation) const
  {
    std::array<double, 6> resultant = {{0., 0., 0., 0., 0., 0.}};
    if (!foundation.enabled || foundation.tie != FoundationTie::material)
      return resultant;
    const std::vector<InterfacePair> &pairs  = pairs_of(set.problem(0));
    const unsigned int                N      = sampling.n_samples();
    const double                      weight = 2. * numbers::PI / N;
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const InterfacePair &pair = pairs[points[i].pair];
        // t = sigma n is the force per unit area that B exerts on A (n out
        // of A): the foundation transmits +t to A if it is B, -t if it is A.
        const double sign = pair.material_b == foundation.id ? 1. :
                            pair.material_a == foundation.id ? -1. :
                                                               0.;
        if (sign == 0.)
          continue;
        const double r = points[i].position[0], z = points[i].position[1];
        for (unsigned int j = 0; j < N; ++j)
          {
            LocalVector t = traction[i * N + j];
            for (unsigned int c = 0; c < 3; ++c)
              t[c] -= points[i].initial_traction[c];
            const double da    = sign * weight * points[i].area_per_radian;
            const double t_r   = t[0] * pair.tangent[0] + t[1] * pair.normal[0];
            const double t_z   = t[0] * pair.tangent[1] + t[1] * pair.normal[1];
            const double theta = sampling.angle(j);
            const double c = std::cos(theta), s = std::sin(theta);
            const double F[3] = {da * (t_r * c - t[2] * s),
                                 da * (t_r * s + t[2] * c),
                                 da * t_z};
            const double x = r * c, y = r * s;
            resultant[0] += F[0];
            resultant[1] += F[1];
            resultant[2] += F[2];
            resultant[3] += y * F[2] - z * F[1];
            resultant[4] += z * F[0] - x * F[2];
            resultant[5] += x * F[1] - y * F[0];
          }
      }
    return resultant;
  }
} // namespace FourierSSI
