#include <base/mpi_session.h>
#include <io/mode_shapes.h>
#include <io/vtu_output.h>
#include <solvers/stability/lowest_eigenpairs.h>

#include <fstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// modes.csv: mode number and eigenvalue per row.
    void
    write_eigenvalues(const Eigenpairs &pairs, const std::string &path)
    {
      std::ofstream csv(path);
      csv.precision(10);
      csv << "mode,eigenvalue\n";
      for (std::size_t k = 0; k < pairs.values.size(); ++k)
        csv << k + 1 << ',' << pairs.values[k] << '\n';
      if (!csv)
        throw std::runtime_error("cannot write \"" + path + "\"");
    }
  } // namespace

  std::vector<std::string>
  write_mode_shapes(const RodModel    &model,
                    const VectorType  &u,
                    const double       load_factor,
                    const unsigned int count,
                    const std::string &directory,
                    const bool         write_vtu)
  {
    MatrixType tangent;
    model.initialize_matrix(tangent);
    model.assemble(u, load_factor, nullptr, &tangent);
    const Eigenpairs pairs = lowest_eigenpairs(tangent,
                                               model.constraints(),
                                               count,
                                               model.multiplier_dofs());
    if (writes_outputs())
      write_eigenvalues(pairs, directory + "/modes.csv");
    if (!write_vtu)
      return {"modes.csv"};
    VtuOutput vtu(model.network(), directory, "modes");
    for (std::size_t k = 0; k < pairs.vectors.size(); ++k)
      vtu.write(k + 1,
                k + 1,
                model,
                moved_along_mode(u,
                                 pairs.vectors[k],
                                 0.1 * model.length_scale()));
    return {"modes.csv", "modes.pvd"};
  }
} // namespace rodnet
