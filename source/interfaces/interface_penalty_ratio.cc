#include <algorithm>
#include <fourier_ssi/interfaces/interface_law.h>
#include <fourier_ssi/interfaces/interface_penalty_ratio.h>
#include <map>

namespace FourierSSI
{
  namespace
  {
    /** The faces of the mesh that lie on a coulomb interface, by its id. */
    std::map<types::boundary_id, std::vector<std::pair<double, double>>>
    coulomb_faces(const InterfaceParameters &interfaces,
                  const MaterialLibrary     &materials,
                  const Triangulation<2>    &triangulation)
    {
      // Per face: (its length, the shear modulus beside it) [m, kPa].
      std::map<types::boundary_id, std::vector<std::pair<double, double>>>
        faces;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary())
              continue;
            const auto law = interfaces.laws.find(face->boundary_id());
            if (law == interfaces.laws.end() ||
                law->second.kind != InterfaceLaw::Kind::coulomb)
              continue;
            const int id = law->second.material >= 0 ?
                             law->second.material :
                             static_cast<int>(cell->material_id());
            if (!materials.has(id))
              continue; // InterfaceIntegrator names the missing material
            const double depth = materials.depth(face->center()[1]);
            faces[face->boundary_id()].emplace_back(
              face->measure(), materials.get(id).shear_modulus(depth));
          }
      return faces;
    }
  } // namespace

  double
  coulomb_penalty_ratio(const InterfaceParameters &interfaces,
                        const MaterialLibrary     &materials,
                        const Triangulation<2>    &triangulation)
  {
    double ratio = 0.;
    for (const auto &[id, faces] :
         coulomb_faces(interfaces, materials, triangulation))
      {
        const InterfaceLaw &law         = interfaces.laws.at(id);
        double              mean_length = 0.;
        for (const auto &face : faces)
          mean_length += face.first / faces.size();
        for (const auto &[length, shear_modulus] : faces)
          {
            const double G_over_l = shear_modulus / mean_length;
            const double kn       = law.automatic_normal ?
                                      automatic_interface_stiffness * G_over_l :
                                      law.normal;
            const double ks       = law.automatic_shear ?
                                      automatic_interface_stiffness * G_over_l :
                                      law.shear;
            ratio = std::max(ratio, std::max(kn, ks) / G_over_l);
          }
      }
    return ratio;
  }
} // namespace FourierSSI
