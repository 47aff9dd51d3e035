#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <fourier_ssi/coupled/initial_stress.h>
#include <fourier_ssi/coupled/nonlinear_soil_points.h>
#include <fourier_ssi/fourier/harmonic_pair_integral.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/linear_algebra/thread_ranges.h>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity";

    /** Strain components 0..3 carry the in-plane factor, 4, 5 the other. */
    ThetaFactor
    factor_of(const unsigned int k)
    {
      return strain_theta_factor(k);
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
  } // namespace

  NonlinearSoilPoints::NonlinearSoilPoints(const HarmonicSet   &set,
                                           const AllParameters &parameters,
                                           const ThetaSampling &sampling)
    : set(set)
    , harmonics(set.get_harmonics())
    , sampling(sampling)
  {
    for (const Harmonic &h : harmonics)
      operators.emplace_back(h);
    make_points(parameters);
    check_initial_stress(parameters);
    if (set.n_owning_ranks() > 1)
      {
        point_stride = set.n_owning_ranks();
        point_rank   = Utilities::MPI::this_mpi_process(set.get_ranks());
      }
  }

  void
  NonlinearSoilPoints::check_initial_stress(
    const AllParameters &parameters) const
  {
    // The geostatic state must be admissible: K0 between the active and
    // passive ratios of Mohr-Coulomb soil, (1 - K0) sigma'_v <= 2 s_u for
    // Tresca. Tolerance: round-off of the stress.
    for (const SoilPoint &point : points)
      {
        double size = 0.;
        for (const double s : point.initial_stress)
          size = std::max(size, std::abs(s));
        const double f = yield_value(point, point.initial_stress);
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
  NonlinearSoilPoints::make_points(const AllParameters &parameters)
  {
    std::map<types::material_id, unsigned int> law_index;
    std::vector<const SoilLaw *>               law_data;
    for (const auto &[id, law] : parameters.soil_plasticity.laws)
      {
        law_index[id] = laws.size();
        laws.emplace_back(law);
        law_data.push_back(&law);
        sands.push_back(law.kind == SoilLaw::Kind::iwan_sand ?
                          std::make_shared<const MultiSurfaceSand>(law) :
                          nullptr);
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
            cell.first_point       = points.size();
            cell.centre            = iterators[0]->center();
            cell.active_cell_index = iterators[0]->active_cell_index();
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
                point.position      = x;
                point.dV            = x[0] * fe_values.JxW(q);
                point.depth         = parameters.materials.depth(x[1]);
                point.shear_modulus = material.shear_modulus(point.depth);
                point.lambda        = material.lambda(point.depth);
                point.law           = law->second;
                point.initial_stress =
                  initial_soil_stress(parameters.initial_stress, point.depth);
                add_hardening_elements(*law_data[point.law], point);
                points.push_back(point);
              }
            cells.push_back(std::move(cell));
          }
        for (auto &it : iterators)
          ++it;
      }
    // Without laws the scene has no soil points: the coupled tangent solver
    // then drives the nonlinear interfaces alone (a swipe on elastic soil).
    AssertThrow(!points.empty() || !parameters.soil_plasticity.any(),
                ExcMessage(entry + "/Laws: no cell of the mesh has a "
                                   "material id with a plastic law"));
  }

  void
  NonlinearSoilPoints::add_hardening_elements(const SoilLaw &law,
                                              SoilPoint     &point)
  {
    if (!law.hardening())
      return;
    if (law.kind == SoilLaw::Kind::iwan)
      {
        // The elements follow G0 and s_u at the point's depth (their
        // profiles); K is the material's, the volume change stays elastic
        // (C1).
        const double bulk_modulus =
          point.lambda + 2. * point.shear_modulus / 3.;
        clays.emplace_back(law, point.shear_modulus, bulk_modulus, point.depth);
        point.clay = clays.size() - 1;
        // A table's elements depend on s_u at the depth: the point's own.
        point.n_elements = clays.back().n_surfaces();
      }
    else
      point.n_elements = sands[point.law]->n_surfaces();
    point.first_history = n_history;
    n_history += std::size_t(sampling.n_samples()) * point.n_elements;
  }

  std::vector<std::vector<StrainVector>>
  NonlinearSoilPoints::strain_amplitudes(
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
  NonlinearSoilPoints::count_over_ranks(SoilYieldCounts &result) const
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

  SoilYieldCounts
  NonlinearSoilPoints::return_map(
    const std::vector<StrainVector> &strain,
    const std::vector<StrainVector> &committed_plastic,
    const std::vector<StrainVector> &committed_history,
    std::vector<StrainVector>       &plastic,
    std::vector<StrainVector>       &history) const
  {
    const unsigned int N = sampling.n_samples();
    plastic.resize(strain.size());
    // Every sample of an owned iwan point is written below; the points
    // other ranks own keep the committed history.
    if (point_stride > 1)
      history = committed_history;
    else
      history.resize(committed_history.size());
    SoilYieldCounts result;
    result.n_elastic           = 0;
    result.n_plastic           = 0;
    result.largest_yield_value = -std::numeric_limits<double>::max();
    // The points on every core of the set (every (point, theta) is
    // independent; the counts and the largest f do not depend on the order:
    // the same bits on any number of threads).
    std::mutex merge;
    for_each_range(
      points.size(),
      16,
      set.n_point_threads(),
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
                StrainVector      *updated = point.n_elements == 0 ?
                                               nullptr :
                                               &history[history_index(point, j)];
                const SoilReturn   r       = return_from(
                  point,
                  strain[k],
                  history_of(p, k, committed_plastic, committed_history),
                  updated);
                for (unsigned int c = 0; c < 6; ++c)
                  plastic[k][c] = elastic[c] - r.stress[c];
                if (r.state == SoilState::elastic)
                  ++n_elastic;
                else
                  ++n_plastic;
                largest = std::max(largest, yield_value(point, r.stress));
              }
          }
        std::lock_guard<std::mutex> lock(merge);
        result.n_elastic += n_elastic;
        result.n_plastic += n_plastic;
        result.largest_yield_value =
          std::max(result.largest_yield_value, largest);
      });
    return result;
  }

  std::vector<Vector<double>>
  NonlinearSoilPoints::load_of(const std::vector<StrainVector> &samples,
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
  NonlinearSoilPoints::cell_load(const SoilCell            &cell,
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
  NonlinearSoilPoints::nodal_force(
    const std::vector<StrainVector>             &strain,
    const std::vector<StrainVector>             &plastic,
    const std::function<bool(const Point<2> &)> &selected) const
  {
    AssertThrow(point_stride == 1,
                ExcMessage("Output/Soil reaction depths: not yet under "
                           "mpirun (the soil's stress lies on several ranks)"));
    const unsigned int          N = sampling.n_samples(), H = set.size();
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
                  stress[j][k] -= plastic[p * N + j][k];
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
  NonlinearSoilPoints::elastic_force(
    const std::vector<Vector<double>> &fields) const
  {
    const unsigned int        N         = sampling.n_samples();
    const StrainAmplitudes    amplitude = strain_amplitudes(fields);
    std::vector<StrainVector> stress    = strain_samples({{1., &amplitude}});
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int j = 0; j < N; ++j)
        stress[p * N + j] = hooke_stress(stress[p * N + j],
                                         points[p].lambda,
                                         points[p].shear_modulus);
    return load_of(stress);
  }

  std::vector<StrainVector>
  NonlinearSoilPoints::strain_samples(
    const std::vector<std::pair<double, const StrainAmplitudes *>> &terms) const
  {
    const unsigned int        N = sampling.n_samples(), H = set.size();
    std::vector<StrainVector> samples(points.size() * N);
    std::vector<double>       a(H), s;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        for (unsigned int k = 0; k < 6; ++k)
          {
            std::fill(a.begin(), a.end(), 0.);
            for (const auto &[factor, amplitudes] : terms)
              if (amplitudes != nullptr && !amplitudes->empty())
                for (unsigned int h = 0; h < H; ++h)
                  a[h] += factor * (*amplitudes)[p][h][k];
            sampling.evaluate(a, factor_of(k), s);
            for (unsigned int j = 0; j < N; ++j)
              samples[p * N + j][k] = s[j];
          }
      }
    return samples;
  }

  std::vector<SoilSample>
  NonlinearSoilPoints::samples_of(
    const std::vector<StrainVector> &strain,
    const std::vector<StrainVector> &previous_plastic,
    const std::vector<StrainVector> &previous_history,
    const std::vector<StrainVector> &plastic) const
  {
    const unsigned int      N = sampling.n_samples();
    std::vector<SoilSample> samples(points.size() * N);
    const StrainVector      at_rest = {{0., 0., 0., 0., 0., 0.}};
    // At rest (no step before): zero s_p and virgin elements.
    const std::vector<StrainVector> rest_plastic(
      previous_plastic.empty() ? points.size() * N : 0, at_rest);
    const std::vector<StrainVector> rest_history(
      previous_history.empty() ? n_history : 0, at_rest);
    const auto &before_plastic =
      previous_plastic.empty() ? rest_plastic : previous_plastic;
    const auto &before_history =
      previous_history.empty() ? rest_history : previous_history;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        const SoilPoint &point = points[p];
        for (unsigned int j = 0; j < N; ++j)
          {
            const unsigned int  k       = p * N + j;
            const StrainVector &before  = before_plastic[k];
            const StrainVector  elastic = elastic_stress(point, strain[k]);
            SoilSample         &sample  = samples[k];
            StrainVector        step_change;
            for (unsigned int c = 0; c < 6; ++c)
              {
                sample.stress[c] = elastic[c] - plastic[k][c];
                step_change[c]   = plastic[k][c] - before[c];
              }
            sample.plastic_strain =
              compliance_strain(plastic[k], point.lambda, point.shear_modulus);
            sample.plastic_strain_increment =
              compliance_strain(step_change, point.lambda, point.shear_modulus);
            sample.yield_value = yield_value(point, sample.stress);
            sample.plastic =
              return_from(point,
                          strain[k],
                          history_of(p, k, before_plastic, before_history),
                          nullptr)
                .state != SoilState::elastic;
          }
      }
    return samples;
  }

  StrainVector
  NonlinearSoilPoints::elastic_stress(const SoilPoint    &point,
                                      const StrainVector &eps) const
  {
    StrainVector stress = hooke_stress(eps, point.lambda, point.shear_modulus);
    for (unsigned int c = 0; c < 6; ++c)
      stress[c] += point.initial_stress[c];
    return stress;
  }

  NonlinearSoilPoints::SampleHistory
  NonlinearSoilPoints::history_of(
    const unsigned int               p,
    const unsigned int               k,
    const std::vector<StrainVector> &plastic,
    const std::vector<StrainVector> &history) const
  {
    const SoilPoint &point = points[p];
    if (point.n_elements == 0)
      return {&plastic[k], nullptr};
    const unsigned int j = k - p * sampling.n_samples();
    return {&plastic[k], &history[history_index(point, j)]};
  }

  SoilReturn
  NonlinearSoilPoints::return_from(const SoilPoint     &point,
                                   const StrainVector  &strain,
                                   const SampleHistory &committed,
                                   StrainVector        *updated,
                                   StressTangent       *tangent) const
  {
    if (point.clay != numbers::invalid_unsigned_int)
      {
        // sigma = sigma_0 + the elements' stress at eps (C1): the surfaces
        // start centred on the geostatic stress.
        const MultiSurfaceStress r = clays[point.clay].return_map(
          strain, committed.elements, updated, tangent);
        SoilReturn result;
        for (unsigned int c = 0; c < 6; ++c)
          result.stress[c] = point.initial_stress[c] + r.stress[c];
        result.state = r.n_yielding > 0 ? SoilState::plane : SoilState::elastic;
        return result;
      }
    const double G = point.shear_modulus, K = point.lambda + 2. * G / 3.;
    if (sands[point.law])
      {
        // (S1): the elements start from their shares of sigma_0.
        const MultiSurfaceStress r =
          sands[point.law]->return_map(strain,
                                       point.initial_stress,
                                       G,
                                       K,
                                       point.depth,
                                       committed.elements,
                                       updated,
                                       tangent);
        SoilReturn result;
        result.stress = r.stress;
        result.state = r.n_yielding > 0 ? SoilState::plane : SoilState::elastic;
        return result;
      }
    // Trial: sigma_0 + D (eps - eps_p,committed) = elastic - s_p,committed.
    StrainVector trial = elastic_stress(point, strain);
    for (unsigned int c = 0; c < 6; ++c)
      trial[c] -= (*committed.plastic)[c];
    const SoilReturnMapping &law = laws[point.law];
    return tangent == nullptr ?
             law.return_map(trial, G, K, point.depth) :
             law.return_map_with_tangent(trial, G, K, point.depth, *tangent);
  }

  double
  NonlinearSoilPoints::yield_value(const SoilPoint    &point,
                                   const StrainVector &stress) const
  {
    if (sands[point.law])
      return sands[point.law]->yield_function(stress, point.depth);
    if (point.clay == numbers::invalid_unsigned_int)
      return laws[point.law].yield_function(stress, point.depth);
    // sqrt(J2) of sigma - sigma_0: |dev| / sqrt(2) with the shears doubled
    // in the squared norm.
    StrainVector change;
    for (unsigned int c = 0; c < 6; ++c)
      change[c] = stress[c] - point.initial_stress[c];
    const double mean = (change[0] + change[1] + change[2]) / 3.;
    double       j2   = 0.;
    for (unsigned int c = 0; c < 3; ++c)
      j2 += 0.5 * (change[c] - mean) * (change[c] - mean);
    for (unsigned int c = 3; c < 6; ++c)
      j2 += change[c] * change[c];
    return std::sqrt(j2) - clays[point.clay].elements().undrained_strength();
  }

  bool
  NonlinearSoilPoints::softening_at(const SoilPoint        &point,
                                    const StrainVector     &strain,
                                    const SampleHistory    &committed,
                                    std::array<double, 36> &softening) const
  {
    const double     G = point.shear_modulus, lambda = point.lambda;
    StressTangent    d_ep;
    const SoilReturn at = return_from(point, strain, committed, nullptr, &d_ep);
    if (at.state == SoilState::elastic)
      return false;
    // D_e - D_ep, D_ep in closed form
    // (SoilReturnMapping::return_map_with_tangent).
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
  NonlinearSoilPoints::softening_integrals(
    const std::vector<StrainVector> &strain,
    const std::vector<StrainVector> &committed,
    const std::vector<StrainVector> &history) const
  {
    const unsigned int               N = sampling.n_samples();
    std::vector<std::vector<double>> softening(points.size());
    for_each_range(
      points.size(),
      16,
      set.n_point_threads(),
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
                const unsigned int k = p * N + j;
                if (!softening_at(points[p],
                                  strain[k],
                                  history_of(p, k, committed, history),
                                  c))
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
  NonlinearSoilPoints::softening_over_ranks(
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

  std::vector<unsigned int>
  NonlinearSoilPoints::yielding_cells(
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

  std::vector<std::vector<NonlinearSoilPoints::ShapeStrains>>
  NonlinearSoilPoints::shape_strains(
    const std::vector<unsigned int> &yielding) const
  {
    const unsigned int                     n_dofs = component.size();
    std::vector<std::vector<ShapeStrains>> strains(
      yielding.size(), std::vector<ShapeStrains>(set.size()));
    // By cells, on every core (a lone n = 0 too).
    for_each_range(yielding.size(),
                   8,
                   set.n_point_threads(),
                   [&](const unsigned int first, const unsigned int last) {
                     std::vector<StrainVector> b;
                     for (unsigned int y = first; y < last; ++y)
                       for (unsigned int h = 0; h < set.size(); ++h)
                         {
                           const SoilCell    &cell = cells[yielding[y]];
                           const unsigned int n_q  = cell.radius.size();
                           ShapeStrains      &flat = strains[y][h];
                           flat.resize(n_dofs * n_q * 6);
                           b.resize(n_q);
                           for (unsigned int i = 0; i < n_dofs; ++i)
                             {
                               for (unsigned int q = 0; q < n_q; ++q)
                                 b[q] = operators[h].strain_of_component(
                                   component[i],
                                   cell.shape_value[q][i],
                                   cell.shape_grad[q][i],
                                   cell.radius[q]);
                               apply_bbar(cell.projection.get(), b);
                               for (unsigned int q = 0; q < n_q; ++q)
                                 std::copy(b[q].begin(),
                                           b[q].end(),
                                           flat.begin() + (i * n_q + q) * 6);
                             }
                         }
                   });
    return strains;
  }

  void
  NonlinearSoilPoints::add_cell_softening(
    const SoilCell                         &cell,
    const unsigned int                      h,
    const unsigned int                      g,
    const std::vector<std::vector<double>> &softening,
    const ShapeStrains                     &row_strain,
    const ShapeStrains                     &column_strain,
    SofteningScratch                       &scratch,
    FullMatrix<double>                     &local) const
  {
    const unsigned int H = set.size(), HH = H * H, n_dofs = component.size();
    const unsigned int n_q = cell.radius.size();
    // The points of the cell that yield somewhere in theta; the others add
    // nothing.
    scratch.yielding.clear();
    for (unsigned int q = 0; q < n_q; ++q)
      if (!softening[cell.first_point + q].empty())
        scratch.yielding.push_back(q);
    const unsigned int width = 6 * scratch.yielding.size();
    // rows[i][k] = Bbar_h of shape function i and columns[k][j] = dV S_hg
    // Bbar_g of shape function j, k = (yielding point, strain component):
    // local = -rows columns, its inner loop over j contiguous (it
    // vectorizes; a dot product over k would not, being a reduction).
    scratch.rows.resize(n_dofs * width);
    scratch.columns.resize(width * n_dofs);
    for (unsigned int k = 0; k < scratch.yielding.size(); ++k)
      {
        const unsigned int q = scratch.yielding[k];
        const unsigned int p = cell.first_point + q;
        // S_hg of this point, gathered: its 36 entries lie H^2 apart.
        std::array<double, 36> s;
        for (unsigned int e = 0; e < 36; ++e)
          s[e] = points[p].dV * softening[p][e * HH + h * H + g];
        for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const double *b = &column_strain[(j * n_q + q) * 6];
            for (unsigned int a = 0; a < 6; ++a)
              {
                double sum = 0.;
                for (unsigned int e = 0; e < 6; ++e)
                  sum += s[a * 6 + e] * b[e];
                scratch.columns[(6 * k + a) * n_dofs + j] = sum;
              }
            std::copy_n(&row_strain[(j * n_q + q) * 6],
                        6,
                        &scratch.rows[j * width + 6 * k]);
          }
      }
    scratch.row_sum.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        double *const sum = scratch.row_sum.data();
        std::fill_n(sum, n_dofs, 0.);
        for (unsigned int k = 0; k < width; ++k)
          {
            const double b = scratch.rows[i * width + k];
            if (b == 0.)
              continue; // a strain this shape function does not have
            const double *column = &scratch.columns[k * n_dofs];
            for (unsigned int j = 0; j < n_dofs; ++j)
              sum[j] += b * column[j];
          }
        for (unsigned int j = 0; j < n_dofs; ++j)
          local(i, j) = -sum[j];
      }
  }

  std::vector<std::vector<std::vector<types::global_dof_index>>>
  NonlinearSoilPoints::cell_dofs() const
  {
    std::vector<std::vector<std::vector<types::global_dof_index>>> dofs;
    for (const SoilCell &cell : cells)
      dofs.push_back(cell.dof_indices);
    return dofs;
  }

  void
  NonlinearSoilPoints::add_softening(
    const std::vector<StrainVector> &strain,
    const std::vector<StrainVector> &committed_plastic,
    const std::vector<StrainVector> &committed_history,
    CoupledTangent                  &tangent) const
  {
    const unsigned int H = set.size();
    // 1. S_hg = theta integral of factor_h (D_e - D_ep) factor_g per point,
    //    over the samples that yield (harmonic_pair_integral.h); empty: a
    //    point elastic at every theta. softening[p][(a * 6 + b) * H^2 + h *
    //    H + g], the harmonic pair innermost (contiguous in the assembly).
    const std::vector<std::vector<double>> softening =
      softening_integrals(strain, committed_plastic, committed_history);
    // 2. The Bbar strains of the shape functions of the yielding cells once
    //    per build (every block row h needs every column harmonic g).
    const std::vector<unsigned int> yielding = yielding_cells(softening);
    const std::vector<std::vector<ShapeStrains>> strains =
      shape_strains(yielding);
    // 3. Block row h: K_t,hg -= int Bbar_h^T S_hg Bbar_g.
    if (H >= set.n_point_threads())
      add_softening_by_harmonics(yielding, softening, strains, tangent);
    else
      add_softening_by_cells(yielding, softening, strains, tangent);
  }

  void
  NonlinearSoilPoints::add_softening_by_harmonics(
    const std::vector<unsigned int>              &yielding,
    const std::vector<std::vector<double>>       &softening,
    const std::vector<std::vector<ShapeStrains>> &strains,
    CoupledTangent                               &tangent) const
  {
    // Each block row on its harmonic's thread (the owner's under MPI,
    // coupled_tangent.h): no two threads add to one row.
    set.for_each([&](const unsigned int h) {
      if (!set.owns(h))
        return;
      FullMatrix<double> local(component.size(), component.size());
      SofteningScratch   scratch;
      for (unsigned int y = 0; y < yielding.size(); ++y)
        for (unsigned int g = 0; g < set.size(); ++g)
          {
            const SoilCell &cell = cells[yielding[y]];
            add_cell_softening(cell,
                               h,
                               g,
                               softening,
                               strains[y][h],
                               strains[y][g],
                               scratch,
                               local);
            tangent.add(h, g, local, cell.dof_indices[h], cell.dof_indices[g]);
          }
    });
  }

  void
  NonlinearSoilPoints::add_softening_by_cells(
    const std::vector<unsigned int>              &yielding,
    const std::vector<std::vector<double>>       &softening,
    const std::vector<std::vector<ShapeStrains>> &strains,
    CoupledTangent                               &tangent) const
  {
    // Fewer harmonics than cores (a lone n = 0): the cells' matrices of one
    // block row on every core at once, then added on one thread, in cell
    // order (the same sum as by harmonics).
    const unsigned int n_dofs = component.size();
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        if (!set.owns(h))
          continue;
        std::vector<FullMatrix<double>> locals(yielding.size() * set.size());
        for_each_range(yielding.size(),
                       8,
                       set.n_point_threads(),
                       [&](const unsigned int first, const unsigned int last) {
                         SofteningScratch scratch;
                         for (unsigned int y = first; y < last; ++y)
                           for (unsigned int g = 0; g < set.size(); ++g)
                             {
                               FullMatrix<double> &local =
                                 locals[y * set.size() + g];
                               local.reinit(n_dofs, n_dofs);
                               add_cell_softening(cells[yielding[y]],
                                                  h,
                                                  g,
                                                  softening,
                                                  strains[y][h],
                                                  strains[y][g],
                                                  scratch,
                                                  local);
                             }
                       });
        for (unsigned int y = 0; y < yielding.size(); ++y)
          for (unsigned int g = 0; g < set.size(); ++g)
            tangent.add(h,
                        g,
                        locals[y * set.size() + g],
                        cells[yielding[y]].dof_indices[h],
                        cells[yielding[y]].dof_indices[g]);
      }
  }
} // namespace FourierSSI
