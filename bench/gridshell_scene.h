// The large welded lattice the solver benchmarks time (solver_checks,
// lowest_eigenpairs, network_picture): the square lattice of
// scenes/gridshell.prm with n x n cells of span 1, 8 segments per lath (by
// default), its two edges pushed together by a tenth of the span and a
// small uplift.
#ifndef RODNET_BENCH_GRIDSHELL_SCENE_H
#define RODNET_BENCH_GRIDSHELL_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>
#include <solvers/statics/static_solver.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace bench
  {
    /// The gridshell scene with @p cells x @p cells cells of span 1 and
    /// @p segments segments per beam.
    inline std::string
    gridshell_scene(const unsigned int cells, const unsigned int segments = 8)
    {
      std::ostringstream s;
      s << "subsection Geometry\n  set Generator = square lattice\n"
        << "  set Cells = " << cells << ", " << cells << "\n"
        << "  set Beam length = " << 1.0 / cells << "\n"
        << "  set Segments = " << segments << "\nend\n"
        << "subsection Material\n  subsection linear elastic\n"
        << "    set Stiffness input = direct\n    set EA = 1000\n"
        << "    set EI1 = 4\n    set EI2 = 1\n    set GJ = 1\n  end\nend\n"
        << "subsection Supports\n  set Prescribed displacements = ";
      for (unsigned int j = 0; j <= cells; ++j)
        s << (j == 0 ? "" : "; ") << "@n_0_" << j << ": x=0.1 y=0 z=0; @n_"
          << cells << "_" << j << ": x=-0.1 y=0 z=0";
      s << "\nend\nsubsection Loads\n  set Steps = 40\n"
        << "  set Distributed force = 0, 0, 0.01\nend\n";
      return s.str();
    }

    /// The Scene of gridshell_scene(@p cells, @p segments).
    inline Scene
    gridshell(const unsigned int cells, const unsigned int segments = 8)
    {
      dealii::ParameterHandler prm;
      Scene::declare_parameters(prm);
      prm.parse_input_from_string(gridshell_scene(cells, segments));
      return Scene(prm);
    }

    /// Solves @p model's first load step with @p parameters from the
    /// undeformed state into @p u; that step's StepInfo.
    inline StaticSolver::StepInfo
    first_load_step(RodModel                       &model,
                    const StaticSolver::Parameters &parameters,
                    VectorType                     &u)
    {
      StaticSolver::StepInfo first;
      u = model.create_vector();
      try
        {
          StaticSolver(model, parameters)
            .run(u,
                 [&](const StaticSolver::StepInfo &info, const VectorType &) {
                   first = info;
                   throw std::runtime_error("first step done");
                 });
        }
      catch (const std::runtime_error &)
        {
        }
      return first;
    }
  } // namespace bench
} // namespace rodnet

#endif
