// HarmonicProblem, part 4: VTU output of the amplitudes, stresses and
// extra fields (serial, or one piece per rank and the .pvtu record).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/input/atomic_file.h>

namespace FourierSSI
{
  std::vector<std::string>
  HarmonicProblem::write_vtu(
    const std::string                                                 &filename,
    const std::vector<std::pair<std::string, const Vector<double> *>> &extra,
    const bool elastic_stresses) const
  {
    StressPostprocessor postprocessor(harmonic_operator,
                                      parameters.materials,
                                      dilatation_projection);
    DataOut<2>          data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             std::vector<std::string>{"U_radial",
                                                      "V_axial",
                                                      "W_circumferential"});
    if (parameters.output.write_stresses && elastic_stresses)
      data_out.add_data_vector(solution, postprocessor);
    for (const auto &[prefix, field] : extra)
      data_out.add_data_vector(*field,
                               std::vector<std::string>{prefix + "U_radial",
                                                        prefix + "V_axial",
                                                        prefix +
                                                          "W_circumferential"});
    Vector<float> material_ids(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      material_ids(cell->active_cell_index()) = cell->material_id();
    data_out.add_data_vector(material_ids, "material_id");
    if (distributed)
      return write_vtu_pieces(data_out, filename);
    data_out.build_patches(fe->degree);
    AtomicFile file(filename);
    data_out.write_vtu(file.stream());
    file.commit();
    return {filename};
  }

  std::vector<std::string>
  HarmonicProblem::write_vtu_pieces(DataOut<2>        &data_out,
                                    const std::string &filename) const
  {
    // Each rank writes its own cells as NAME.rankR.vtu; rank 0 writes the
    // NAME.pvtu record that ParaView opens.
    const unsigned int rank = distributed->this_rank();
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(distributed->get_communicator());
    Vector<float> ranks(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      ranks(cell->active_cell_index()) =
        distributed->cell_owner(cell->active_cell_index());
    data_out.add_data_vector(ranks, "rank");
    data_out.set_cell_selection(
      [this, rank](const typename Triangulation<2>::cell_iterator &cell) {
        return cell->is_active() &&
               distributed->cell_owner(cell->active_cell_index()) == rank;
      });
    data_out.build_patches(fe->degree);
    const std::string base =
      filename.size() > 4 && filename.substr(filename.size() - 4) == ".vtu" ?
        filename.substr(0, filename.size() - 4) :
        filename;
    const auto piece = [&](const unsigned int r) {
      return base + ".rank" + std::to_string(r) + ".vtu";
    };
    std::vector<std::string> written = {piece(rank)};
    AtomicFile               out(piece(rank));
    data_out.write_vtu(out.stream());
    out.commit();
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          {
            const std::string p = piece(r);
            pieces.push_back(p.substr(p.find_last_of('/') + 1));
          }
        AtomicFile record(base + ".pvtu");
        data_out.write_pvtu_record(record.stream(), pieces);
        record.commit();
        written.push_back(base + ".pvtu");
      }
    return written;
  }
} // namespace FourierSSI
