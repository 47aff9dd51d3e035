#include <deal.II/base/exceptions.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <tuple>

namespace FourierSSI
{
  namespace
  {
    using VectorRange =
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>;

    /** The per-row names and the vector ranges DataOutBase expects. */
    std::pair<std::vector<std::string>, std::vector<VectorRange>>
    names_and_ranges(const std::vector<VtuField> &fields)
    {
      std::vector<std::string> names;
      std::vector<VectorRange> vectors;
      for (const VtuField &field : fields)
        {
          if (field.n_components > 1)
            vectors.emplace_back(
              names.size(),
              names.size() + field.n_components - 1,
              field.name,
              DataComponentInterpretation::component_is_part_of_vector);
          names.insert(names.end(), field.n_components, field.name);
        }
      return {names, vectors};
    }
  } // namespace

  template <int dim>
  void
  write_patches_vtu(const std::vector<DataOutBase::Patch<dim, 3>> &patches,
                    const std::vector<VtuField>                   &fields,
                    const std::string                             &filename)
  {
    const auto [names, vectors] = names_and_ranges(fields);
    AtomicFile file(filename);
    DataOutBase::write_vtu(
      patches, names, vectors, DataOutBase::VtkFlags(), file.stream());
    file.commit();
  }

  void
  write_point_samples_vtu(const std::vector<Point<3>>            &points,
                          const std::vector<VtuField>            &fields,
                          const std::vector<std::vector<double>> &values,
                          const std::string                      &filename)
  {
    AssertThrow(values.size() == fields.size(),
                ExcMessage("VTU output: one value list per field"));
    unsigned int n_rows = 0;
    for (const VtuField &field : fields)
      n_rows += field.n_components;
    std::vector<DataOutBase::Patch<0, 3>> patches(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        patches[p].vertices[0] = points[p];
        patches[p].patch_index = p;
        patches[p].data.reinit(n_rows, 1);
        unsigned int row = 0;
        for (unsigned int f = 0; f < fields.size(); ++f)
          for (unsigned int c = 0; c < fields[f].n_components; ++c, ++row)
            patches[p].data(row, 0) = values[f][p * fields[f].n_components + c];
      }
    write_patches_vtu(patches, fields, filename);
  }

  template void
  write_patches_vtu<0>(const std::vector<DataOutBase::Patch<0, 3>> &,
                       const std::vector<VtuField> &,
                       const std::string &);
  template void
  write_patches_vtu<2>(const std::vector<DataOutBase::Patch<2, 3>> &,
                       const std::vector<VtuField> &,
                       const std::string &);
  template void
  write_patches_vtu<3>(const std::vector<DataOutBase::Patch<3, 3>> &,
                       const std::vector<VtuField> &,
                       const std::string &);
} // namespace FourierSSI
