#include <cstdint>
#include <cstring>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <ostream>
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

    /**
     * One inline binary DataArray: base64 of the UInt32 byte count followed
     * by the numbers (VTK's header_type UInt32, little endian as this
     * machine), encoded together as VTK reads uncompressed data.
     */
    template <typename Number>
    void
    write_binary_array(std::ostream              &out,
                       const std::string         &attributes,
                       const std::vector<Number> &numbers)
    {
      AssertThrow(numbers.size() * sizeof(Number) <= UINT32_MAX,
                  ExcMessage("VTU output: a data array above 4 GB"));
      const std::uint32_t        n_bytes = numbers.size() * sizeof(Number);
      std::vector<unsigned char> bytes(sizeof(n_bytes) + n_bytes);
      std::memcpy(bytes.data(), &n_bytes, sizeof(n_bytes));
      if (n_bytes > 0)
        std::memcpy(bytes.data() + sizeof(n_bytes), numbers.data(), n_bytes);
      out << "<DataArray " << attributes << " format=\"binary\">\n"
          << Utilities::encode_base64(bytes) << "\n</DataArray>\n";
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

  void
  write_quad_surface_vtu(const std::vector<std::array<Point<3>, 4>> &quads,
                         const std::vector<VtuField>                &fields,
                         const std::vector<std::vector<double>>     &values,
                         const std::string                          &filename)
  {
    AssertThrow(values.size() == fields.size(),
                ExcMessage("VTU output: one value list per field"));
    for (unsigned int f = 0; f < fields.size(); ++f)
      AssertThrow(values[f].size() == quads.size() * fields[f].n_components,
                  ExcMessage("VTU output: field " + fields[f].name +
                             " has not one value per quad and component"));
    // The header says LittleEndian and the numbers are this machine's.
    const std::uint16_t one = 1;
    AssertThrow(*reinterpret_cast<const unsigned char *>(&one) == 1,
                ExcMessage("VTU output: Float64 surfaces are written on "
                           "little-endian machines only"));
    // Each quad comes with its own four vertices (no search for shared
    // ones): cell data needs no connectivity between quads, and ParaView's
    // Clean filter merges coincident points where that is wanted.
    std::vector<double>       points;
    std::vector<std::int32_t> connectivity, offsets;
    std::vector<std::uint8_t> types(quads.size(), 9); // VTK_QUAD
    for (unsigned int q = 0; q < quads.size(); ++q)
      {
        for (unsigned int v = 0; v < 4; ++v)
          {
            for (unsigned int d = 0; d < 3; ++d)
              points.push_back(quads[q][v][d]);
            connectivity.push_back(4 * q + v);
          }
        offsets.push_back(4 * (q + 1));
      }
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << 4 * quads.size()
        << "\" NumberOfCells=\"" << quads.size() << "\">\n<Points>\n";
    write_binary_array(out,
                       "type=\"Float64\" NumberOfComponents=\"3\"",
                       points);
    out << "</Points>\n<Cells>\n";
    write_binary_array(out,
                       "type=\"Int32\" Name=\"connectivity\"",
                       connectivity);
    write_binary_array(out, "type=\"Int32\" Name=\"offsets\"", offsets);
    write_binary_array(out, "type=\"UInt8\" Name=\"types\"", types);
    out << "</Cells>\n<CellData>\n";
    for (unsigned int f = 0; f < fields.size(); ++f)
      write_binary_array(out,
                         "type=\"Float64\" Name=\"" + fields[f].name +
                           "\" NumberOfComponents=\"" +
                           std::to_string(fields[f].n_components) + "\"",
                         values[f]);
    out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    file.commit();
  }

  void
  write_pvd_series(const std::vector<std::pair<double, std::string>> &steps,
                   const std::string                                 &filename)
  {
    AtomicFile file(filename);
    DataOutBase::write_pvd_record(file.stream(), steps);
    file.commit();
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
