// The welded square lattice of issue 33 and 37, the benchmark of networks:
// beams of length 0.1 m in 10 segments, EA = 1e5, EI = 400 and 100,
// GJ = 67, pinned at its four corners, under its weight (0.05 kg/m) in two
// load steps. Its models live on MPI_COMM_WORLD: on several processes they
// are distributed (RodModel::finalize).
#ifndef RODNET_BENCH_WELDED_LATTICE_H
#define RODNET_BENCH_WELDED_LATTICE_H

#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>

#include <memory>
#include <sstream>

namespace rodnet
{
  namespace bench
  {
    /// The lattice with @p cells x @p cells cells.
    inline std::unique_ptr<RodModel>
    welded_lattice(const unsigned int cells)
    {
      std::ostringstream scene;
      scene << "subsection Geometry\n  set Generator = square lattice\n"
            << "  set Cells = " << cells << ", " << cells << "\n"
            << "  set Beam length = 0.1\n  set Segments = 10\nend\n"
            << "subsection Material\n  subsection linear elastic\n"
            << "    set Stiffness input = direct\n    set EA = 1e5\n"
            << "    set EI1 = 400\n    set EI2 = 100\n    set GJ = 67\n"
            << "  end\nend\nsubsection Supports\n  set Pinned vertices = "
            << "@n_0_0, @n_" << cells << "_0, @n_0_" << cells << ", @n_"
            << cells << "_" << cells << "\nend\nsubsection Loads\n"
            << "  set Steps = 2\n  set Gravity = 0, 0, -9.81\n"
            << "  set Mass per length = 0.05\nend\n";
      dealii::ParameterHandler prm;
      Scene::declare_parameters(prm);
      prm.parse_input_from_string(scene.str());
      return Scene(prm).build_model();
    }
  } // namespace bench
} // namespace rodnet

#endif
