#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_soil_solver.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/coupled/safeguarded_newton.h>
#include <fourier_ssi/fourier/harmonic_pair_integral.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/linear_algebra/thread_ranges.h>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <mutex>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity";

    /**
     * The acceleration of the out-of-balance iteration: Newton updates are
     * taken as they are (relaxing them by Aitken or Anderson was measured
     * to double the iterations, doc/soil-plasticity.md section 3); the
     * initial-stiffness iteration takes Load path/Acceleration.
     */
    LoadPathParameters::Acceleration
    acceleration_of(const LoadPathParameters &settings, const bool tangent)
    {
      return tangent ? LoadPathParameters::Acceleration::none :
                       settings.acceleration;
    }

    /** How the log names the iteration. */
    std::string
    iteration_name(const LoadPathParameters &settings, const bool tangent)
    {
      using Acceleration = LoadPathParameters::Acceleration;
      if (tangent)
        return "Newton on the coupled tangent, backtracking";
      return settings.acceleration == Acceleration::aitken ?
               "initial stiffness, Aitken" :
             settings.acceleration == Acceleration::anderson ?
               "initial stiffness, Anderson" :
               "initial stiffness";
    }

    /** Strain components 0..3 carry the in-plane factor, 4, 5 the other. */
    ThetaFactor
    factor_of(const unsigned int k)
    {
      return k < 4 ? ThetaFactor::in_plane : ThetaFactor::circumferential;
    }

    /**
     * B-bar on a cell's strain field: the dilatation replaced by its
     * projection (with_dilatation). Applied to a stress field it is also
     * the transpose: sum_q dV Bbar^T s = sum_q dV B^T bar(s), since the
     * r-weighted projection is self-adjoint (doc/soil-plasticity.md 3).
     */
    void
    apply_bbar(const LinearProjection    *projection,
               std::vector<StrainVector> &field)
    {
      if (projection == nullptr || !projection->valid)
        return;
      std::vector<double> trace(field.size());
      for (unsigned int q = 0; q < field.size(); ++q)
        trace[q] = field[q][0] + field[q][1] + field[q][2];
      const auto c = projection->project(trace);
      for (unsigned int q = 0; q < field.size(); ++q)
        field[q] = with_dilatation(field[q], projection->value_at(c, q));
    }

    /**
     * fields[h] := its sum over the ranks the harmonics are distributed
     * over (one sum; on one rank nothing): each field computed by its
     * harmonic's owner, zero elsewhere, becomes the same bits on every rank.
     */
    void
    sum_fields_over_ranks(const HarmonicSet           &set,
                          std::vector<Vector<double>> &fields)
    {
      if (set.n_owning_ranks() == 1)
        return;
      std::vector<double> flat;
      for (const Vector<double> &field : fields)
        flat.insert(flat.end(), field.begin(), field.end());
      set.sum_over_ranks(flat);
      auto next = flat.begin();
      for (Vector<double> &field : fields)
        {
          std::copy(next, next + field.size(), field.begin());
          next += field.size();
        }
    }

    /**
     * Some nonlinear interface holds faces that can open by multipliers
     * (NonlinearInterfacePoints::augments: `contact`, or a coulomb law with
     * a tension cut-off above Newton's cap). Its samples are then
     * 2 n_max + 1, one per value of the band-limited gap (more ask it to
     * vanish where it has no values, and the multipliers at the contact
     * edge drift; constrained_theta_samples()).
     */
    bool
    holds_gaps_by_multipliers(const HarmonicSet   &set,
                              const AllParameters &parameters)
    {
      const InterfaceIntegrator *interfaces = set.problem(0).get_interfaces();
      if (interfaces == nullptr || !parameters.interfaces.any_nonlinear())
        return false;
      const std::vector<InterfacePair> &pairs = interfaces->get_pairs();
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          const InterfaceLaw &law =
            parameters.interfaces.laws.at(pairs[i].boundary_id);
          if (law.can_open() && NonlinearInterfacePoints::augments(
                                  law,
                                  interfaces->get_law_stiffness()[i],
                                  interfaces->get_stiffness()[i],
                                  true))
            return true;
        }
      return false;
    }

    /** The rigid motion of fields given per harmonic (rigid_motion_of). */
    RigidMotion
    motion_of_fields(const HarmonicSet                 &set,
                     const std::vector<Vector<double>> &fields)
    {
      return rigid_motion_of(set, [&fields](const unsigned int h) {
        return fields[h];
      });
    }
  } // namespace

  CoupledSoilSolver::CoupledSoilSolver(const HarmonicSet   &set,
                                       const AllParameters &parameters)
    : LoadPathStates(set, parameters, "kNm")
    , set(set)
    , parameters(parameters)
    , settings(parameters.load_path)
    , harmonics(set.get_harmonics())
    , sampling(harmonics,
               theta_samples_for(highest_harmonic(harmonics),
                                 parameters.load_path.theta_samples))
    , interface_sampling(harmonics,
                         holds_gaps_by_multipliers(set, parameters) ?
                           minimum_theta_samples(highest_harmonic(harmonics)) :
                           sampling.n_samples())
  {
    for (const Harmonic &h : harmonics)
      operators.emplace_back(h);
    check_homogeneous_constraints(entry, "plastic soil");
    make_points();
    check_initial_stress();
    if (parameters.interfaces.any_nonlinear())
      // Coulomb laws above the soil cap (soil_iteration_stiffness) through
      // the multipliers (on interface_sampling).
      interface =
        std::make_unique<NonlinearInterfacePoints>(set, parameters, true);
    if (set.n_owning_ranks() > 1)
      {
        point_stride = set.n_owning_ranks();
        point_rank   = Utilities::MPI::this_mpi_process(set.get_ranks());
      }
    // A swipe's mu and K^-1 e_V are solved on the owner of harmonic 0 and
    // read there; not written for distributed harmonics yet.
    AssertThrow(!parameters.rigid_foundation.swipes() ||
                  set.n_owning_ranks() == 1,
                ExcMessage("Rigid foundation/Held motions: not yet: a swipe "
                           "('w' with a Held vertical force) on several MPI "
                           "ranks; run it on one rank"));
    solve_load_pattern();
    solve_held_loads();
    start_at_rest();
    committed.plastic.assign(points.size() * sampling.n_samples(),
                             {{0., 0., 0., 0., 0., 0.}});
    if (interface)
      {
        committed.interface_plastic.assign(interface->size() *
                                             interface_sampling.n_samples(),
                                           {{0., 0., 0.}});
        committed.interface_origin = committed.interface_plastic;
        committed.interface_slip   = committed.interface_plastic;
      }
  }

  void
  CoupledSoilSolver::check_initial_stress() const
  {
    // The geostatic state must be admissible: K0 between the active and
    // passive ratios of Mohr-Coulomb soil, (1 - K0) sigma'_v <= 2 s_u for
    // Tresca. Tolerance: round-off of the stress.
    for (const SoilPoint &point : points)
      {
        double size = 0.;
        for (const double s : point.initial_stress)
          size = std::max(size, std::abs(s));
        const double f =
          laws[point.law].yield_function(point.initial_stress, point.depth);
        if (f <= 1e-12 * std::max(size, 1.))
          continue;
        const auto law =
          std::next(parameters.soil_plasticity.laws.begin(), point.law);
        std::ostringstream message;
        message << std::setprecision(4)
                << "Initial stress/K0: the geostatic stress at depth "
                << point.depth << " m violates the yield condition of "
                << "material " << static_cast<unsigned int>(law->first)
                << " (Soil plasticity/Laws; f = " << f << " kPa > 0): K0 = "
                << parameters.initial_stress.earth_pressure_coefficient
                << " must lie between the active and passive ratios "
                   "(Mohr-Coulomb), (1 - K0) sigma'_v within 2 s_u (Tresca)";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }

  void
  CoupledSoilSolver::make_points()
  {
    std::map<types::material_id, unsigned int> law_index;
    for (const auto &[id, law] : parameters.soil_plasticity.laws)
      {
        law_index[id] = laws.size();
        laws.push_back(law);
      }
    const DoFHandler<2> &dofs0 = set.problem(0).get_dof_handler();
    const auto          &fe    = dofs0.get_fe();
    // The stiffness's own quadrature (HarmonicProblem), so that a field
    // with eps_p = eps gives back exactly the soil part of K u.
    FEValues<2> fe_values(fe,
                          QGauss<2>(fe.degree + 2),
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    const bool  bbar =
      parameters.discretization.volumetric == VolumetricStrain::bbar &&
      fe.degree == 2;
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    for (unsigned int i = 0; i < n_dofs; ++i)
      component.push_back(fe.system_to_component_index(i).first);
    std::vector<typename DoFHandler<2>::active_cell_iterator> iterators;
    for (unsigned int h = 0; h < set.size(); ++h)
      iterators.push_back(set.problem(h).get_dof_handler().begin_active());
    for (; iterators[0] != dofs0.end();)
      {
        const auto law = law_index.find(iterators[0]->material_id());
        if (law != law_index.end())
          {
            fe_values.reinit(iterators[0]);
            SoilCell cell;
            cell.first_point = points.size();
            cell.centre      = iterators[0]->center();
            for (unsigned int h = 0; h < set.size(); ++h)
              {
                std::vector<types::global_dof_index> indices(n_dofs);
                iterators[h]->get_dof_indices(indices);
                cell.dof_indices.push_back(indices);
              }
            if (bbar)
              cell.projection = std::make_shared<LinearProjection>(fe_values);
            const ElasticMaterial &material =
              parameters.materials.get(iterators[0]->material_id());
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const Point<2> &x = fe_values.quadrature_point(q);
                cell.radius.push_back(x[0]);
                cell.shape_value.emplace_back(n_dofs);
                cell.shape_grad.emplace_back(n_dofs);
                for (unsigned int i = 0; i < n_dofs; ++i)
                  {
                    cell.shape_value[q][i] = fe_values.shape_value(i, q);
                    cell.shape_grad[q][i]  = fe_values.shape_grad(i, q);
                  }
                SoilPoint point;
                point.cell          = cells.size();
                point.q             = q;
                point.r             = x[0];
                point.dV            = x[0] * fe_values.JxW(q);
                point.depth         = parameters.materials.depth(x[1]);
                point.shear_modulus = material.shear_modulus(point.depth);
                point.lambda        = material.lambda(point.depth);
                point.law           = law->second;
                point.initial_stress =
                  parameters.initial_stress.soil_stress(point.depth);
                points.push_back(point);
              }
            cells.push_back(std::move(cell));
          }
        for (auto &it : iterators)
          ++it;
      }
    AssertThrow(!points.empty(),
                ExcMessage(entry + "/Laws: no cell of the mesh has a "
                                   "material id with a plastic law"));
  }

  void
  CoupledSoilSolver::solve_load_pattern()
  {
    loads          = LoadPattern(set);
    pattern_strain = strain_amplitudes(loads.solution);
    if (interface)
      pattern_relative =
        interface->relative_displacements(loads.solution, interface_sampling);
  }

  void
  CoupledSoilSolver::solve_held_loads()
  {
    if (!loads.holds_loads())
      return;
    held_strain = strain_amplitudes(loads.held_solution);
    if (interface)
      held_relative = interface->relative_displacements(loads.held_solution,
                                                        interface_sampling);
    if (parameters.rigid_foundation.swipes())
      {
        loads.add_swipe_pattern(set);
        swipe_strain = strain_amplitudes(loads.swipe_solution);
        if (interface)
          swipe_relative =
            interface->relative_displacements(loads.swipe_solution,
                                              interface_sampling);
      }
  }

  double
  CoupledSoilSolver::applied_load_norm(const StepState &state) const
  {
    return loads.applied_norm(state.load_factor, state.held_fraction);
  }

  std::vector<std::vector<StrainVector>>
  CoupledSoilSolver::strain_amplitudes(
    const std::vector<Vector<double>> &fields) const
  {
    std::vector<std::vector<StrainVector>> result(
      points.size(), std::vector<StrainVector>(set.size()));
    // Harmonics concurrently: each writes its own column.
    set.for_each([&](const unsigned int h) {
      if (!set.owns(h))
        return;
      std::vector<StrainVector> cell_strain;
      for (const SoilCell &cell : cells)
        {
          const unsigned int n_q = cell.radius.size();
          cell_strain.resize(n_q);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              std::array<double, 3>       values = {{0., 0., 0.}};
              std::array<Tensor<1, 2>, 3> gradients;
              for (unsigned int i = 0; i < cell.shape_value[q].size(); ++i)
                {
                  const double u = fields[h](cell.dof_indices[h][i]);
                  values[component[i]] += u * cell.shape_value[q][i];
                  gradients[component[i]] += u * cell.shape_grad[q][i];
                }
              cell_strain[q] =
                operators[h].strain(values, gradients, cell.radius[q]);
            }
          apply_bbar(cell.projection.get(), cell_strain);
          for (unsigned int q = 0; q < n_q; ++q)
            result[cell.first_point + q][h] = cell_strain[q];
        }
    });
    // Every harmonic's amplitudes on every rank (the first sum of an
    // iteration; load_of makes the second). Each entry is non-zero on its
    // owner only, so the sum is exact and the same bits on every rank,
    // whatever the reduction order.
    if (set.n_owning_ranks() > 1)
      {
        const unsigned int  H = set.size();
        std::vector<double> flat(points.size() * H * 6);
        for (unsigned int p = 0; p < points.size(); ++p)
          for (unsigned int h = 0; h < H; ++h)
            std::copy(result[p][h].begin(),
                      result[p][h].end(),
                      flat.begin() + (p * H + h) * 6);
        set.sum_over_ranks(flat);
        for (unsigned int p = 0; p < points.size(); ++p)
          for (unsigned int h = 0; h < H; ++h)
            std::copy(flat.begin() + (p * H + h) * 6,
                      flat.begin() + (p * H + h + 1) * 6,
                      result[p][h].begin());
      }
    return result;
  }

  void
  CoupledSoilSolver::count_over_ranks(SoilStepResult &result) const
  {
    if (point_stride == 1)
      return;
    std::vector<double> counts = {static_cast<double>(result.n_elastic),
                                  static_cast<double>(result.n_plastic)};
    set.sum_over_ranks(counts);
    result.n_elastic = static_cast<unsigned int>(counts[0]);
    result.n_plastic = static_cast<unsigned int>(counts[1]);
    result.largest_yield_value =
      Utilities::MPI::max(result.largest_yield_value, set.get_ranks());
  }

  std::vector<StrainVector>
  CoupledSoilSolver::strain_samples(
    const std::vector<Vector<double>> &correction,
    const double                       load_factor,
    const double                       held_fraction,
    const double                       swipe_force) const
  {
    const unsigned int        N = sampling.n_samples(), H = set.size();
    const auto                amplitude = strain_amplitudes(correction);
    std::vector<StrainVector> samples(points.size() * N);
    std::vector<double>       a(H), s;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        for (unsigned int k = 0; k < 6; ++k)
          {
            for (unsigned int h = 0; h < H; ++h)
              a[h] =
                amplitude[p][h][k] + load_factor * pattern_strain[p][h][k] +
                (held_strain.empty() ? 0. :
                                       held_fraction * held_strain[p][h][k]);
            if (!swipe_strain.empty())
              for (unsigned int h = 0; h < H; ++h)
                a[h] += swipe_force * swipe_strain[p][h][k];
            sampling.evaluate(a, factor_of(k), s);
            for (unsigned int j = 0; j < N; ++j)
              samples[p * N + j][k] = s[j];
          }
      }
    return samples;
  }

  std::vector<LocalVector>
  CoupledSoilSolver::relative_samples(
    const std::vector<Vector<double>> &correction,
    const double                       load_factor,
    const double                       held_fraction,
    const double                       swipe_force) const
  {
    std::vector<LocalVector> relative =
      interface->relative_displacements(correction, interface_sampling);
    for (unsigned int k = 0; k < relative.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        relative[k][c] +=
          load_factor * pattern_relative[k][c] +
          (held_relative.empty() ? 0. : held_fraction * held_relative[k][c]) +
          (swipe_relative.empty() ? 0. : swipe_force * swipe_relative[k][c]);
    return relative;
  }

  void
  CoupledSoilSolver::return_map(const std::vector<StrainVector> &strain,
                                std::vector<StrainVector>       &plastic,
                                SoilStepResult                  &result) const
  {
    const unsigned int N = sampling.n_samples();
    plastic.resize(strain.size());
    result.n_elastic           = 0;
    result.n_plastic           = 0;
    result.largest_yield_value = -std::numeric_limits<double>::max();
    // The points on the harmonic set's threads (every (point, theta) is
    // independent; the counts and the largest f do not depend on the order:
    // the same bits on any number of threads).
    std::mutex merge;
    for_each_range(
      points.size(),
      16,
      set.n_threads(),
      [&](const unsigned int first, const unsigned int last) {
        unsigned int n_elastic = 0, n_plastic = 0;
        double       largest = -std::numeric_limits<double>::max();
        for (unsigned int p = first; p < last; ++p)
          {
            if (!owns_point(p))
              continue;
            const SoilPoint &point = points[p];
            for (unsigned int j = 0; j < N; ++j)
              {
                const unsigned int k = p * N + j;
                // s_p = sigma_0 + D eps - sigma keeps the internal force
                // int Bbar^T (sigma - sigma_0) = K u - c.
                const StrainVector elastic = elastic_stress(point, strain[k]);
                const SoilReturn   r = return_from_committed(point, k, elastic);
                for (unsigned int c = 0; c < 6; ++c)
                  plastic[k][c] = elastic[c] - r.stress[c];
                if (r.state == SoilState::elastic)
                  ++n_elastic;
                else
                  ++n_plastic;
                largest = std::max(largest,
                                   laws[point.law].yield_function(r.stress,
                                                                  point.depth));
              }
          }
        std::lock_guard<std::mutex> lock(merge);
        result.n_elastic += n_elastic;
        result.n_plastic += n_plastic;
        result.largest_yield_value =
          std::max(result.largest_yield_value, largest);
      });
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::load_of(const std::vector<StrainVector> &samples,
                             const bool                       condensed) const
  {
    const unsigned int          N = sampling.n_samples(), H = set.size();
    std::vector<Vector<double>> load(H);
    for (unsigned int h = 0; h < H; ++h)
      load[h].reinit(set.problem(h).get_dof_handler().n_dofs());
    // Theta integrals int factor_h s dtheta per point, component, harmonic.
    std::vector<std::vector<StrainVector>> integral(
      points.size(), std::vector<StrainVector>(H));
    std::vector<char>   any(points.size(), 0);
    std::vector<double> s(N), coefficient;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        for (unsigned int j = 0; j < N; ++j)
          for (unsigned int k = 0; k < 6; ++k)
            any[p] = any[p] || samples[p * N + j][k] != 0.;
        if (!any[p])
          continue; // an elastic point: no load, no work
        for (unsigned int k = 0; k < 6; ++k)
          {
            for (unsigned int j = 0; j < N; ++j)
              s[j] = samples[p * N + j][k];
            sampling.integrate(s, factor_of(k), coefficient);
            for (unsigned int h = 0; h < H; ++h)
              integral[p][h][k] = coefficient[h];
          }
      }
    // Every point's theta integrals on every rank (each non-zero on the
    // rank that return-maps the point: an exact sum), then G_h of every
    // harmonic redundantly, as the serial run assembles it.
    if (point_stride > 1)
      {
        const unsigned int  size = H * 6 + 1;
        std::vector<double> flat(points.size() * size, 0.);
        for (unsigned int p = 0; p < points.size(); ++p)
          if (owns_point(p) && any[p])
            {
              for (unsigned int h = 0; h < H; ++h)
                std::copy(integral[p][h].begin(),
                          integral[p][h].end(),
                          flat.begin() + p * size + h * 6);
              flat[p * size + H * 6] = 1.;
            }
        set.sum_over_ranks(flat);
        for (unsigned int p = 0; p < points.size(); ++p)
          {
            any[p] = flat[p * size + H * 6] != 0.;
            for (unsigned int h = 0; h < H; ++h)
              std::copy(flat.begin() + p * size + h * 6,
                        flat.begin() + p * size + (h + 1) * 6,
                        integral[p][h].begin());
          }
      }
    set.for_each([&](const unsigned int h) {
      std::vector<StrainVector> field;
      for (const SoilCell &cell : cells)
        {
          const unsigned int n_q    = cell.radius.size();
          bool               active = false;
          field.resize(n_q);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              field[q] = integral[cell.first_point + q][h];
              active   = active || any[cell.first_point + q];
            }
          if (!active)
            continue; // only the points that yield cost work
          const Vector<double> local = cell_load(cell, h, field);
          if (condensed)
            set.problem(h)
              .get_homogeneous_constraints()
              .distribute_local_to_global(local, cell.dof_indices[h], load[h]);
          else
            for (unsigned int i = 0; i < local.size(); ++i)
              load[h](cell.dof_indices[h][i]) += local(i);
        }
    });
    return load;
  }

  Vector<double>
  CoupledSoilSolver::cell_load(const SoilCell            &cell,
                               const unsigned int         h,
                               std::vector<StrainVector> &field) const
  {
    apply_bbar(cell.projection.get(), field);
    const unsigned int n_dofs = component.size();
    Vector<double>     local(n_dofs);
    for (unsigned int q = 0; q < cell.radius.size(); ++q)
      {
        const double dV = points[cell.first_point + q].dV;
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const StrainVector b =
              operators[h].strain_of_component(component[i],
                                               cell.shape_value[q][i],
                                               cell.shape_grad[q][i],
                                               cell.radius[q]);
            double sum = 0.;
            for (unsigned int k = 0; k < 6; ++k)
              sum += b[k] * field[q][k];
            local(i) += sum * dV;
          }
      }
    return local;
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::soil_nodal_force(
    const std::function<bool(const Point<2> &)> &selected) const
  {
    AssertThrow(point_stride == 1,
                ExcMessage("Output/Soil reaction depths: not yet under "
                           "mpirun (the soil's stress lies on several ranks)"));
    const unsigned int N = sampling.n_samples(), H = set.size();
    const auto         strain = strain_samples(committed.correction_solution,
                                       committed.load_factor,
                                       committed.held_fraction);
    std::vector<Vector<double>> force(H);
    for (unsigned int h = 0; h < H; ++h)
      force[h].reinit(set.problem(h).get_dof_handler().n_dofs());
    std::vector<double>                    s(N), coefficient;
    std::vector<std::vector<StrainVector>> field(H);
    for (const SoilCell &cell : cells)
      {
        if (!selected(cell.centre))
          continue;
        const unsigned int n_q = cell.radius.size();
        for (auto &f : field)
          f.assign(n_q, StrainVector());
        // The stress less the geostatic sigma_0 (balanced by self-weight):
        // D eps - s_p, theta-integrated against each harmonic's factor.
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int        p     = cell.first_point + q;
            const SoilPoint          &point = points[p];
            std::vector<StrainVector> stress(N);
            for (unsigned int j = 0; j < N; ++j)
              {
                stress[j] = hooke_stress(strain[p * N + j],
                                         point.lambda,
                                         point.shear_modulus);
                for (unsigned int k = 0; k < 6; ++k)
                  stress[j][k] -= committed.plastic[p * N + j][k];
              }
            for (unsigned int k = 0; k < 6; ++k)
              {
                for (unsigned int j = 0; j < N; ++j)
                  s[j] = stress[j][k];
                sampling.integrate(s, factor_of(k), coefficient);
                for (unsigned int h = 0; h < H; ++h)
                  field[h][q][k] = coefficient[h];
              }
          }
        for (unsigned int h = 0; h < H; ++h)
          {
            const Vector<double> local = cell_load(cell, h, field[h]);
            for (unsigned int i = 0; i < local.size(); ++i)
              force[h](cell.dof_indices[h][i]) += local(i);
          }
      }
    return force;
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::soil_force(const std::vector<Vector<double>> &fields) const
  {
    const unsigned int        N = sampling.n_samples();
    std::vector<StrainVector> strain(points.size() * N);
    const auto                amplitude = strain_amplitudes(fields);
    std::vector<double>       a(set.size()), s;
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int k = 0; k < 6; ++k)
        {
          for (unsigned int h = 0; h < set.size(); ++h)
            a[h] = amplitude[p][h][k];
          sampling.evaluate(a, factor_of(k), s);
          for (unsigned int j = 0; j < N; ++j)
            strain[p * N + j][k] = s[j];
        }
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int j = 0; j < N; ++j)
        strain[p * N + j] = hooke_stress(strain[p * N + j],
                                         points[p].lambda,
                                         points[p].shear_modulus);
    return load_of(strain);
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::out_of_balance_load(
    const std::vector<Vector<double>> &fields)
  {
    std::vector<StrainVector> plastic;
    SoilStepResult            result;
    return_map(strain_samples(fields, 0., 0.), plastic, result);
    std::vector<Vector<double>> load = load_of(plastic);
    if (interface)
      {
        std::vector<LocalVector> interface_plastic;
        InterfaceSnapshot        snapshot;
        add_interface_load(relative_samples(fields, 0., 0.),
                           committed.interface_origin,
                           interface_plastic,
                           snapshot,
                           load);
      }
    return load;
  }

  ContactCounts
  CoupledSoilSolver::add_interface_load(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &origin,
    std::vector<LocalVector>       &plastic,
    InterfaceSnapshot              &snapshot,
    std::vector<Vector<double>>    &load) const
  {
    snapshot.relative          = relative;
    const ContactCounts counts = interface->return_map(
      relative, origin, plastic, snapshot.traction, snapshot.state);
    const std::vector<Vector<double>> interface_load =
      interface->load_of(plastic, interface_sampling);
    for (unsigned int h = 0; h < set.size(); ++h)
      load[h] += interface_load[h];
    return counts;
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::tangent_product(const std::vector<Vector<double>> &fields,
                                     const std::vector<Vector<double>> &x)
  {
    update_tangent(strain_samples(fields, 0., 0.),
                   interface ? relative_samples(fields, 0., 0.) :
                               std::vector<LocalVector>(),
                   committed.interface_origin);
    std::vector<Vector<double>> y;
    tangent->vmult(y, x);
    return y;
  }

  double
  CoupledSoilSolver::controlled_motion(const unsigned int    h,
                                       const Vector<double> &v) const
  {
    const RigidFoundation *foundation = set.problem(h).get_foundation();
    AssertThrow(foundation != nullptr,
                ExcMessage("Load path/Control: displacement "
                           "control needs a Rigid foundation"));
    return controlled_component(foundation->motion(v), settings.motion);
  }

  double
  CoupledSoilSolver::controlled_load_factor(const StepState &state,
                                            const double     target) const
  {
    const Harmonic wanted = controlled_harmonic(settings.motion);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (harmonics[h].n == wanted.n && harmonics[h].family == wanted.family)
        {
          // The motions by the pattern and now, from the owner of h (the
          // others add zeros: exact).
          std::vector<double> motion = {0., 0.};
          if (set.owns(h))
            {
              motion[0] = controlled_motion(h, loads.solution[h]);
              motion[1] = controlled_motion(h, state.correction_solution[h]);
              if (!loads.held_solution.empty())
                motion[1] += state.held_fraction *
                             controlled_motion(h, loads.held_solution[h]);
            }
          set.sum_over_ranks(motion);
          const double by_pattern = motion[0], now = motion[1];
          AssertThrow(by_pattern != 0.,
                      ExcMessage("Load path/Controlled motion: "
                                 "the Rigid foundation loads do not drive "
                                 "this motion (give the load that does)"));
          return (target - now) / by_pattern;
        }
    AssertThrow(false,
                ExcMessage("Load path/Controlled motion: its "
                           "harmonic is not solved"));
    return 0.;
  }

  std::array<double, 2>
  CoupledSoilSolver::swipe_multipliers(const RigidMotion &now,
                                       const RigidMotion &by_pattern,
                                       const RigidMotion &by_swipe,
                                       const double       target,
                                       const double       settlement,
                                       const bool displacement_control) const
  {
    const auto m = [this](const RigidMotion &motion) {
      return controlled_component(motion, settings.motion);
    };
    // Row 1: the controlled motion (or lambda itself), row 2: w.
    const double a   = displacement_control ? m(by_pattern) : 1.,
                 b   = displacement_control ? m(by_swipe) : 0.,
                 e   = displacement_control ? target - m(now) : target;
    const double c   = by_pattern.vertical_displacement,
                 d   = by_swipe.vertical_displacement,
                 f   = settlement - now.vertical_displacement;
    const double det = a * d - b * c;
    AssertThrow(det != 0.,
                ExcMessage("Rigid foundation/Held motions: the swipe's "
                           "vertical load does not move w, or the Rigid "
                           "foundation loads do not drive the Load "
                           "path/Controlled motion with w held"));
    return {{(e * d - b * f) / det, (a * f - e * c) / det}};
  }

  void
  CoupledSoilSolver::set_swipe_multipliers(
    StepState   &state,
    const double target,
    const bool   displacement_control) const
  {
    // The state without lambda and mu: K^-1 c + rho u_held.
    const RigidMotion now = rigid_motion_of(set, [&](const unsigned int h) {
      return loads.total_displacement(h,
                                      0.,
                                      state.correction_solution[h],
                                      state.held_fraction);
    });
    const auto [load_factor, swipe_force] =
      swipe_multipliers(now,
                        motion_of_fields(set, loads.solution),
                        motion_of_fields(set, loads.swipe_solution),
                        target,
                        swipe_settlement,
                        displacement_control);
    state.load_factor = load_factor;
    state.swipe_force = swipe_force;
  }

  StrainVector
  CoupledSoilSolver::elastic_stress(const SoilPoint    &point,
                                    const StrainVector &eps) const
  {
    StrainVector stress = hooke_stress(eps, point.lambda, point.shear_modulus);
    for (unsigned int c = 0; c < 6; ++c)
      stress[c] += point.initial_stress[c];
    return stress;
  }

  SoilReturn
  CoupledSoilSolver::return_from_committed(const SoilPoint    &point,
                                           const unsigned int  k,
                                           const StrainVector &elastic) const
  {
    // Trial: sigma_0 + D (eps - eps_p,committed) = elastic - s_p,committed.
    StrainVector trial = elastic;
    for (unsigned int c = 0; c < 6; ++c)
      trial[c] -= committed.plastic[k][c];
    const double G = point.shear_modulus;
    return laws[point.law].return_map(trial,
                                      G,
                                      point.lambda + 2. * G / 3.,
                                      point.depth);
  }

  bool
  CoupledSoilSolver::softening_at(const unsigned int      p,
                                  const unsigned int      k,
                                  const StrainVector     &strain,
                                  std::array<double, 36> &softening) const
  {
    const SoilPoint &point = points[p];
    const double     G = point.shear_modulus, lambda = point.lambda;
    // Trial: sigma_0 + D (eps - eps_p,committed), as return_from_committed.
    StrainVector trial = elastic_stress(point, strain);
    for (unsigned int c = 0; c < 6; ++c)
      trial[c] -= committed.plastic[k][c];
    StressTangent    d_ep;
    const SoilReturn at = laws[point.law].return_map_with_tangent(
      trial, G, lambda + 2. * G / 3., point.depth, d_ep);
    if (at.state == SoilState::elastic)
      return false;
    // D_e - D_ep, D_ep in closed form (SoilLaw::return_map_with_tangent).
    for (unsigned int l = 0; l < 6; ++l)
      {
        StrainVector unit{};
        unit[l]                    = 1.;
        const StrainVector elastic = hooke_stress(unit, lambda, G);
        for (unsigned int a = 0; a < 6; ++a)
          softening[a * 6 + l] = elastic[a] - d_ep[a * 6 + l];
      }
    return true;
  }

  std::vector<std::vector<double>>
  CoupledSoilSolver::softening_integrals(
    const std::vector<StrainVector> &strain) const
  {
    const unsigned int               N = sampling.n_samples();
    std::vector<std::vector<double>> softening(points.size());
    for_each_range(
      points.size(),
      16,
      set.n_threads(),
      [&](const unsigned int first, const unsigned int last) {
        std::array<double, 36> c;
        HarmonicPairIntegral   integral(harmonics, sampling, 6, 4);
        for (unsigned int p = first; p < last; ++p)
          {
            if (!owns_point(p))
              continue; // its strain samples are on its own rank
            bool yields = false;
            for (unsigned int j = 0; j < N; ++j)
              {
                if (!softening_at(p, p * N + j, strain[p * N + j], c))
                  continue;
                if (!yields)
                  {
                    integral.clear();
                    yields = true;
                  }
                integral.add_sample(j, c.data());
              }
            if (yields)
              integral.integrals(softening[p]);
          }
      });
    softening_over_ranks(softening);
    return softening;
  }

  void
  CoupledSoilSolver::softening_over_ranks(
    std::vector<std::vector<double>> &softening) const
  {
    if (point_stride == 1)
      return;
    // 1. Which points yield: one flag per point, set by its rank.
    std::vector<double> yields(points.size(), 0.);
    for (unsigned int p = 0; p < points.size(); ++p)
      yields[p] = softening[p].empty() ? 0. : 1.;
    set.sum_over_ranks(yields);
    // 2. Their integrals, packed in the points' order: each is non-zero on
    //    one rank only, so the sum is exact (x + 0 = x), the serial bits.
    const unsigned int  H = set.size(), size = 36 * H * H;
    std::vector<double> packed;
    for (unsigned int p = 0; p < points.size(); ++p)
      if (yields[p] != 0.)
        {
          if (softening[p].empty())
            packed.resize(packed.size() + size, 0.);
          else
            packed.insert(packed.end(),
                          softening[p].begin(),
                          softening[p].end());
        }
    set.sum_over_ranks(packed);
    for (unsigned int p = 0, next = 0; p < points.size(); ++p)
      if (yields[p] != 0.)
        {
          softening[p].assign(packed.begin() + next,
                              packed.begin() + next + size);
          next += size;
        }
  }

  void
  CoupledSoilSolver::make_tangent()
  {
    std::vector<std::vector<std::vector<types::global_dof_index>>> dofs;
    for (const SoilCell &cell : cells)
      dofs.push_back(cell.dof_indices);
    // The coulomb interfaces' pairs couple the harmonics too.
    if (interface)
      for (auto &pair : interface->pair_dofs())
        dofs.push_back(std::move(pair));
    tangent = std::make_unique<CoupledTangent>(set, dofs);
  }

  std::vector<unsigned int>
  CoupledSoilSolver::yielding_cells(
    const std::vector<std::vector<double>> &softening) const
  {
    std::vector<unsigned int> yielding;
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (unsigned int q = 0; q < cells[c].radius.size(); ++q)
        if (!softening[cells[c].first_point + q].empty())
          {
            yielding.push_back(c);
            break;
          }
    return yielding;
  }

  std::vector<std::vector<CoupledSoilSolver::ShapeStrains>>
  CoupledSoilSolver::shape_strains(
    const std::vector<unsigned int> &yielding) const
  {
    const unsigned int                     n_dofs = component.size();
    std::vector<std::vector<ShapeStrains>> strains(
      yielding.size(), std::vector<ShapeStrains>(set.size()));
    set.for_each([&](const unsigned int h) {
      for (unsigned int y = 0; y < yielding.size(); ++y)
        {
          const SoilCell    &cell = cells[yielding[y]];
          const unsigned int n_q  = cell.radius.size();
          ShapeStrains       b(n_dofs, std::vector<StrainVector>(n_q));
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              for (unsigned int q = 0; q < n_q; ++q)
                b[i][q] =
                  operators[h].strain_of_component(component[i],
                                                   cell.shape_value[q][i],
                                                   cell.shape_grad[q][i],
                                                   cell.radius[q]);
              apply_bbar(cell.projection.get(), b[i]);
            }
          strains[y][h] = std::move(b);
        }
    });
    return strains;
  }

  void
  CoupledSoilSolver::add_cell_softening(
    const SoilCell                         &cell,
    const unsigned int                      h,
    const unsigned int                      g,
    const std::vector<std::vector<double>> &softening,
    const ShapeStrains                     &row_strain,
    const ShapeStrains                     &column_strain,
    FullMatrix<double>                     &local) const
  {
    const unsigned int H = set.size(), HH = H * H, n_dofs = component.size();
    local = 0.;
    for (unsigned int q = 0; q < cell.radius.size(); ++q)
      {
        const unsigned int p = cell.first_point + q;
        if (softening[p].empty())
          continue;
        const double *s  = &softening[p][h * H + g];
        const double  dV = points[p].dV;
        for (unsigned int j = 0; j < n_dofs; ++j)
          {
            StrainVector sb{};
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int e = 0; e < 6; ++e)
                sb[a] += s[(a * 6 + e) * HH] * column_strain[j][q][e];
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                double sum = 0.;
                for (unsigned int a = 0; a < 6; ++a)
                  sum += row_strain[i][q][a] * sb[a];
                local(i, j) -= dV * sum;
              }
          }
      }
  }

  void
  CoupledSoilSolver::update_tangent(
    const std::vector<StrainVector> &strain,
    const std::vector<LocalVector>  &relative,
    const std::vector<LocalVector>  &interface_origin,
    const bool                       displacement_control)
  {
    const unsigned int H = set.size();
    // 1. S_hg = theta integral of factor_h (D_e - D_ep) factor_g per point,
    //    over the samples that yield (harmonic_pair_integral.h); empty: a
    //    point elastic at every theta. softening[p][(a * 6 + b) * H^2 + h *
    //    H + g], the harmonic pair innermost (contiguous in the assembly).
    const std::vector<std::vector<double>> softening =
      softening_integrals(strain);
    // 2. K_t = diag(K_h) - the softening of the yielding cells, block row h
    //    by harmonic h's thread; the Bbar strains of the shape functions of
    //    the yielding cells once per build (every block row h needs every
    //    column harmonic g).
    if (!tangent)
      make_tangent();
    tangent->reset_to_elastic();
    const std::vector<unsigned int> yielding = yielding_cells(softening);
    const std::vector<std::vector<ShapeStrains>> strains =
      shape_strains(yielding);
    // Block row h: K_t,hg -= int Bbar_h^T S_hg Bbar_g (on h's owner under
    // MPI, coupled_tangent.h).
    set.for_each([&](const unsigned int h) {
      if (!set.owns(h))
        return;
      FullMatrix<double> local(component.size(), component.size());
      for (unsigned int y = 0; y < yielding.size(); ++y)
        for (unsigned int g = 0; g < H; ++g)
          {
            const SoilCell &cell = cells[yielding[y]];
            add_cell_softening(
              cell, h, g, softening, strains[y][h], strains[y][g], local);
            tangent->add(h, g, local, cell.dof_indices[h], cell.dof_indices[g]);
          }
    });
    // 3. The interfaces' part: -int B_h^T (D - D_t) B_g at the samples
    //    that slip or open.
    if (interface)
      interface->add_softening(relative,
                               interface_origin,
                               interface_sampling,
                               *tangent);
    if (displacement_control)
      add_control_stiffening();
    tangent->factorize();
    tangent_pattern.resize(H);
    for (unsigned int h = 0; h < H; ++h)
      tangent_pattern[h] = loads.load[h];
    // F_h is on h's owner only (LoadPattern); the solve takes all of F.
    sum_fields_over_ranks(set, tangent_pattern);
    tangent->solve(tangent_pattern);
  }

  void
  CoupledSoilSolver::add_control_stiffening()
  {
    stiffen_motion(controlled_harmonic(settings.motion),
                   [this](const RigidMotion &m) {
                     return controlled_component(m, settings.motion);
                   });
    if (swiping)
      stiffen_motion({0, Family::symmetric}, [](const RigidMotion &m) {
        return m.vertical_displacement;
      });
  }

  void
  CoupledSoilSolver::stiffen_motion(
    const Harmonic                                   &wanted,
    const std::function<double(const RigidMotion &)> &component)
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      if (harmonics[h].n == wanted.n && harmonics[h].family == wanted.family)
        {
          const RigidFoundation *foundation = set.problem(h).get_foundation();
          const std::set<types::global_dof_index> master_set =
            foundation->master_dofs();
          const std::vector<types::global_dof_index> masters(master_set.begin(),
                                                             master_set.end());
          const SparseMatrix<double> &K = set.problem(h).get_system_matrix();
          // c_k = m(e_k) on each master DoF; alpha scales c c^T to the
          // masters' own stiffness.
          Vector<double>      unit(K.m());
          std::vector<double> c(masters.size());
          double              diagonal = 0., c_squared = 0.;
          for (unsigned int k = 0; k < masters.size(); ++k)
            {
              unit[masters[k]] = 1.;
              c[k]             = component(foundation->motion(unit));
              unit[masters[k]] = 0.;
              diagonal =
                std::max(diagonal, std::abs(K.diag_element(masters[k])));
              c_squared += c[k] * c[k];
            }
          if (c_squared == 0.)
            continue;
          const double       alpha = diagonal / c_squared;
          FullMatrix<double> local(masters.size(), masters.size());
          for (unsigned int i = 0; i < masters.size(); ++i)
            for (unsigned int j = 0; j < masters.size(); ++j)
              local(i, j) = alpha * c[i] * c[j];
          tangent->add(h, h, local, masters, masters);
        }
  }

  std::vector<Vector<double>>
  CoupledSoilSolver::tangent_correction(
    const std::vector<Vector<double>> &residual,
    const bool                         displacement_control) const
  {
    std::vector<Vector<double>> du = residual;
    tangent->solve(du);
    double load_change = 0., swipe_change = 0.;
    // A swipe: K_t^-1 e_V (one more solve with the factorization).
    std::vector<Vector<double>> swipe_pattern;
    if (swiping)
      {
        swipe_pattern = loads.swipe_load;
        tangent->solve(swipe_pattern);
        // The iterate holds both motions already: du must keep them.
        const std::array<double, 2> changes =
          swipe_multipliers(motion_of_fields(set, du),
                            motion_of_fields(set, tangent_pattern),
                            motion_of_fields(set, swipe_pattern),
                            0.,
                            0.,
                            displacement_control);
        load_change  = changes[0];
        swipe_change = changes[1];
      }
    else if (displacement_control)
      {
        const Harmonic wanted = controlled_harmonic(settings.motion);
        for (unsigned int h = 0; h < set.size(); ++h)
          if (harmonics[h].n == wanted.n &&
              harmonics[h].family == wanted.family)
            {
              const double by_pattern =
                controlled_motion(h, tangent_pattern[h]);
              if (by_pattern != 0.)
                load_change = -controlled_motion(h, du[h]) / by_pattern;
            }
      }
    std::vector<Vector<double>> change(set.size());
    set.for_each([&](const unsigned int h) {
      change[h].reinit(du[h].size());
      if (!set.owns(h))
        return; // K_h is on its owner only
      du[h].add(load_change, tangent_pattern[h]);
      if (swiping)
        du[h].add(swipe_change, swipe_pattern[h]);
      set.problem(h).get_system_matrix().vmult(change[h], du[h]);
      change[h].add(-load_change, loads.load[h]);
      if (swiping)
        change[h].add(-swipe_change, loads.swipe_load[h]);
      set.problem(h).get_homogeneous_constraints().set_zero(change[h]);
    });
    sum_fields_over_ranks(set, change);
    return change;
  }

  CoupledSoilSolver::Evaluation
  CoupledSoilSolver::evaluate(const StepState &state,
                              SoilStepResult  &result) const
  {
    Evaluation e;
    // 1-2: strains at every (point, theta), the return mapping.
    e.strain = strain_samples(state.correction_solution,
                              state.load_factor,
                              state.held_fraction,
                              state.swipe_force);
    return_map(e.strain, e.plastic, result);
    // 3-4: out-of-balance load and force residual R = G - c; the coulomb
    //    interfaces add theirs (one c for both sources).
    e.residual = load_of(e.plastic);
    const double interface_load_norm =
      interface ? add_interface_residual(state, e, result) : 0.;
    for (unsigned int h = 0; h < set.size(); ++h)
      e.residual[h] -= state.correction_load[h];
    e.residual_norm = norm_over_harmonics(e.residual);
    // The scale is |lambda F| and the interfaces' G (kn times a gap, the
    // internal force of a stiff penalty), never the soil's G: that is D
    // times the plastic strain, which grows without bound when the soil
    // collapses, and would pass a residual of any size.
    e.scale = {applied_load_norm(state), interface_load_norm};
    return e;
  }

  double
  CoupledSoilSolver::add_interface_residual(const StepState &state,
                                            Evaluation      &e,
                                            SoilStepResult  &result) const
  {
    e.relative = relative_samples(state.correction_solution,
                                  state.load_factor,
                                  state.held_fraction,
                                  state.swipe_force);
    std::vector<Vector<double>> interface_load(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      interface_load[h].reinit(e.residual[h].size());
    result.contact    = add_interface_load(e.relative,
                                        state.interface_origin,
                                        e.interface_plastic,
                                        result.interface_state,
                                        interface_load);
    const double norm = norm_over_harmonics(interface_load);
    for (unsigned int h = 0; h < set.size(); ++h)
      e.residual[h] += interface_load[h];
    result.largest_interface_yield_value =
      interface->largest_yield_value(result.interface_state.traction);
    return norm;
  }

  void
  CoupledSoilSolver::accept(Evaluation        &e,
                            const unsigned int iteration,
                            StepState         &state,
                            SoilStepResult    &result) const
  {
    count_over_ranks(result);
    state.plastic           = std::move(e.plastic);
    state.interface_plastic = std::move(e.interface_plastic);
    if (interface)
      {
        // Exact contact keeps its slip apart; its origin carries lambda = t
        // into the next step (NonlinearInterfacePoints::commit_augmented).
        interface->commit_augmented(e.relative,
                                    result.interface_state.traction,
                                    state.interface_slip,
                                    state.interface_plastic);
        state.interface_origin = state.interface_plastic;
      }
    result.iterations = iteration;
    result.residual   = e.scale.relative(e.residual_norm);
  }

  CoupledSoilSolver::Correction
  CoupledSoilSolver::newton_correction(const Evaluation &e,
                                       const StepState  &state,
                                       const bool        displacement_control)
  {
    // Rebuilt at every update: keeping it for 3-10 updates (modified
    // Newton) was measured slower (doc/soil-plasticity.md 3b).
    update_tangent(e.strain,
                   e.relative,
                   state.interface_origin,
                   displacement_control);
    return correction_of(tangent_correction(e.residual, displacement_control));
  }

  CoupledSoilSolver::Correction
  CoupledSoilSolver::correction_of(std::vector<Vector<double>> load) const
  {
    std::vector<std::vector<Vector<double>>> increment(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      increment[h] = {load[h]};
    set.solve_increments(increment);
    Correction correction;
    correction.load = std::move(load);
    for (unsigned int h = 0; h < set.size(); ++h)
      correction.solution.push_back(std::move(increment[h][0]));
    return correction;
  }

  void
  CoupledSoilSolver::add_correction(const double      alpha,
                                    const Correction &correction,
                                    StepState        &state) const
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        state.correction_load[h].add(alpha, correction.load[h]);
        // A harmonic's displacement is on its owner only.
        if (set.owns(h))
          state.correction_solution[h].add(alpha, correction.solution[h]);
      }
  }

  bool
  CoupledSoilSolver::solve_step(const double    target,
                                const bool      holding,
                                StepState      &state,
                                SoilStepResult &result)
  {
    // Holding: the held loads come on at a fixed load factor.
    if (holding)
      state.held_fraction = target;
    // A swipe holds w from the end of the held stage on.
    swiping = !holding && parameters.rigid_foundation.swipes();
    Evaluation   e;
    unsigned int iterations = 0;
    const auto   converge   = [&]() {
      return iterate(target, holding, state, result, e, iterations);
    };
    // With contact interfaces the multipliers move between converged
    // iterations (augmented Lagrangian).
    const auto move_multipliers = [&](const unsigned int update) {
      return interface->update_and_test_multipliers(
        result.interface_state.traction,
        state.interface_slip,
        interface_sampling,
        state.interface_origin,
        settings.tolerance * e.scale.largest(),
        update);
    };
    const bool converged =
      interface ?
        interface->iterate_with_multipliers(converge,
                                            move_multipliers,
                                            result.multiplier_updates) :
        converge();
    if (converged)
      accept(e, iterations, state, result);
    return converged;
  }

  CoupledSoilSolver::Evaluation
  CoupledSoilSolver::evaluate_at(const double    target,
                                 const bool      holding,
                                 StepState      &state,
                                 SoilStepResult &result)
  {
    const bool displacement_control =
      !holding && settings.control == LoadPathParameters::Control::displacement;
    if (swiping)
      set_swipe_multipliers(state, target, displacement_control);
    else if (!holding)
      state.load_factor =
        displacement_control ? controlled_load_factor(state, target) : target;
    return evaluate(state, result);
  }

  bool
  CoupledSoilSolver::iterate(const double    target,
                             const bool      holding,
                             StepState      &state,
                             SoilStepResult &result,
                             Evaluation     &e,
                             unsigned int   &iterations)
  {
    const bool displacement_control =
      !holding && settings.control == LoadPathParameters::Control::displacement;
    const bool tangent_stiffness = parameters.soil_plasticity.tangent;
    FixedPointAcceleration acceleration(acceleration_of(settings,
                                                        tangent_stiffness),
                                        settings.anderson_depth);
    const auto             evaluate_iterate = [&](StepState &iterate) {
      return evaluate_at(target, holding, iterate, result);
    };
    // The globalisation (safeguarded_newton.h): a full step that raises |R|
    // is halved at once, down to 1/16, and the step is cut if even that
    // does not lower |R|. Going on from a worse plastic state wanders off
    // (measured: |R| / |F| up to 1e6 at a plateau, where the tangent is
    // near-singular; with 4 non-improving steps allowed, pile-adhesion
    // converged to a state 20 rad off), and taking initial-stiffness updates
    // instead of cutting made steps that a cut settles 4-10 times slower
    // (doc/soil-plasticity.md 3b). Those updates are the retry after the
    // last cut only (retry_persistently).
    using Newton = SafeguardedNewton<StepState, Evaluation, Correction>;
    Newton newton(
      Newton::Settings{0, 1. / 16., 20},
      evaluate_iterate,
      [&](const Evaluation &at, const StepState &iterate) {
        return newton_correction(at, iterate, displacement_control);
      },
      [&](const double alpha, const Correction &dc, StepState &iterate) {
        add_correction(alpha, dc, iterate);
      });
    e                    = evaluate_iterate(state);
    bool newton_fallback = false;
    for (unsigned int iteration = 0; iteration <= settings.maximum_iterations;
         ++iteration)
      {
        if (!std::isfinite(e.residual_norm))
          return false;
        if (e.scale.converged(e.residual_norm, settings.tolerance))
          {
            iterations += iteration;
            return true;
          }
        if (tangent_stiffness)
          {
            // No decrease along the Newton direction: cut (soil_newton).
            if (newton.update(state, e))
              continue;
            // No descent: the step is cut, unless this is its retry after
            // the last cut (retry_persistently): then one initial-stiffness
            // update, Newton going on from there, until |R| stalls.
            if (!persistent || newton.stalled())
              return false;
            newton_fallback = true;
          }
        add_correction(1.,
                       correction_of(acceleration.increment(
                         state.correction_load, e.residual)),
                       state);
        e = evaluate_iterate(state);
        if (newton_fallback)
          newton.restart(), newton_fallback = false;
      }
    return false;
  }

  std::vector<std::pair<FoundationMotion, double>>
  CoupledSoilSolver::held_reactions(
    const StepState         &state,
    const InterfaceSnapshot &interface_state) const
  {
    if (parameters.rigid_foundation.reported_motions().empty())
      return {};
    std::vector<Vector<double>> nonlinear_load = load_of(state.plastic, false);
    if (interface)
      {
        const std::vector<Vector<double>> interface_load =
          interface->load_of(interface->spring_plastic(interface_state),
                             interface_sampling,
                             false);
        for (unsigned int h = 0; h < set.size(); ++h)
          nonlinear_load[h] += interface_load[h];
      }
    return held_reactions_of(state, nonlinear_load);
  }

  Vector<double>
  CoupledSoilSolver::held_load(const unsigned int h) const
  {
    return held_stage_load(set.problem(h));
  }

  double
  CoupledSoilSolver::load_work() const
  {
    // Per harmonic on its owner, summed in the harmonics' order.
    std::vector<double> parts(set.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        {
          Vector<double> load = loads.load[h];
          load *= committed.load_factor;
          if (!loads.held_solution.empty())
            load.add(committed.held_fraction, held_load(h));
          if (!loads.swipe_load.empty())
            load.add(committed.swipe_force, loads.swipe_load[h]);
          parts[h] = load * total_displacement(committed, h);
        }
    return sum_over_harmonics(set, parts, 1)[0];
  }

  void
  CoupledSoilSolver::run(std::ostream &log)
  {
    const bool load_control =
      settings.control == LoadPathParameters::Control::load;
    log << "plastic soil: " << points.size() << " quadrature points x "
        << sampling.n_samples() << " theta samples, " << set.size()
        << " harmonics"
        << (set.n_owning_ranks() > 1 ?
              " distributed over " + std::to_string(set.n_owning_ranks()) +
                " MPI ranks" :
              std::string())
        << ", " << (load_control ? "load" : "displacement") << " control, "
        << settings.load_steps << " steps, tolerance " << settings.tolerance
        << ", " << iteration_name(settings, parameters.soil_plasticity.tangent)
        << (cells.front().projection ? ", B-bar" : "") << '\n';
    if (interface)
      interface->describe(log,
                          interface_sampling.n_samples(),
                          highest_harmonic(harmonics));
    write_held_motions(log, "");
    LoadPath(settings, entry, *this).run(log);
    if (set.n_owning_ranks() > 1)
      log << "  MPI: " << set.n_rank_sums()
          << " sums over the ranks (strain amplitudes and theta integrals "
             "every iteration, the controlled motion under displacement "
             "control, a few per step; with Stiffness = tangent the "
             "softening, the tangent's values and the load correction "
             "every Newton update), "
          << set.rank_sum_time()
          << " s in them on rank 0 (computing or waiting for the others)\n";
  }

  void
  CoupledSoilSolver::extrapolate(const StepState &before_last,
                                 const double     ratio,
                                 StepState       &state) const
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        state.correction_load[h].add(ratio, committed.correction_load[h]);
        state.correction_load[h].add(-ratio, before_last.correction_load[h]);
        state.correction_solution[h].add(ratio,
                                         committed.correction_solution[h]);
        state.correction_solution[h].add(-ratio,
                                         before_last.correction_solution[h]);
      }
  }

  bool
  CoupledSoilSolver::solve_trial(const double target, const bool holding)
  {
    trial_result         = SoilStepResult();
    const bool converged = solve_step(target, holding, trial, trial_result);
    persistent           = false;
    return converged;
  }

  bool
  CoupledSoilSolver::retry_persistently(std::ostream &log)
  {
    if (!parameters.soil_plasticity.tangent)
      return false;
    persistent = true;
    log << "  step retried at that size, Newton going on with an "
           "initial-stiffness update where it finds no descent\n";
    return true;
  }

  void
  CoupledSoilSolver::commit_trial(const LoadStep &step,
                                  const bool      holding,
                                  std::ostream   &log)
  {
    SoilStepResult &result = trial_result;
    commit(result, step);
    if (holding)
      swipe_settlement = result.motion.vertical_displacement;
    result.held_reactions = held_reactions(committed, result.interface_state);
    steps.push_back(result);
    if (step_observer)
      step_observer(result);
    log << "  step " << steps.size() << (holding ? " (held loads): " : ": ");
    write_foundation_state(log, result);
    log << "; " << result.iterations << " iterations; plastic samples "
        << result.n_plastic << " of " << result.n_plastic + result.n_elastic
        << "; max f " << result.largest_yield_value << " kPa";
    if (interface)
      {
        log << "; interface stick/slip/open " << result.contact[0] << '/'
            << result.contact[1] << '/' << result.contact[2];
        interface->write_multiplier_updates(log,
                                            result.multiplier_updates,
                                            result.interface_state.relative);
      }
    log << "; " << result.time << " s" << std::endl;
  }

  void
  CoupledSoilSolver::write_foundation_state(std::ostream         &log,
                                            const SoilStepResult &result) const
  {
    // The loads the scene applies (as in load-displacement.csv: M about the
    // reference point), each with the motion it works on.
    const RigidFoundationParameters &f = parameters.rigid_foundation;
    const auto loads = applied_loads(result.load_factor, result.held_fraction);
    const RigidMotion &motion = result.motion;
    const bool         moment = f.moment != 0. || f.held_moment != 0.;
    const bool         torque = f.torque != 0. || f.held_torque != 0.;
    log << "V " << vertical_force_of(loads, result.swipe_force) << " kN, H "
        << loads[0] << " kN";
    if (moment)
      log << ", M " << moment_about_reference(loads, f) << " kNm";
    if (torque)
      log << ", T " << loads[5] << " kNm";
    log << "; w " << motion.vertical_displacement << " m, u "
        << motion.horizontal_displacement << " m";
    if (moment)
      log << ", rotation " << motion.rotation << " rad";
    if (torque)
      log << ", twist " << motion.twist << " rad";
    write_held_reactions(log, result);
  }

  void
  CoupledSoilSolver::write_interface_state_csv(
    const std::string &filename) const
  {
    AssertThrow(interface != nullptr,
                ExcMessage(entry + ": the scene has no nonlinear interface"));
    std::vector<InterfaceSnapshot> snapshots;
    for (const SoilStepResult &step : steps)
      snapshots.push_back(step.interface_state);
    interface->write_state_csv(filename, snapshots, interface_sampling);
  }

  void
  CoupledSoilSolver::write_csv(const std::string &filename) const
  {
    // The loads that hold the held motions, or a direction probe's H and M,
    // one column each: the H and M columns before them are the applied
    // drive.
    const std::string reaction_header =
      steps.empty() ? std::string() :
                      held_reaction_columns(parameters.rigid_foundation,
                                            steps.back().held_reactions);
    write_load_step_csv(filename,
                        steps,
                        parameters.rigid_foundation,
                        "elastic,plastic,max_yield_kPa,time_s,held_fraction,"
                        "stick,slip,open" +
                          reaction_header,
                        [](std::ostream &out, const SoilStepResult &r) {
                          out << r.n_elastic << ',' << r.n_plastic << ','
                              << r.largest_yield_value << ',' << r.time << ','
                              << r.held_fraction << ',' << r.contact[0] << ','
                              << r.contact[1] << ',' << r.contact[2];
                          for (const auto &reaction : r.held_reactions)
                            out << ',' << reaction.second;
                        });
  }
} // namespace FourierSSI
