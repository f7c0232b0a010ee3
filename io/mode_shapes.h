#ifndef RODNET_IO_MODE_SHAPES_H
#define RODNET_IO_MODE_SHAPES_H

#include <core/rod_model.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Writes the @p count lowest eigenpairs of the constrained tangent of
   * @p model at the state @p u and load factor @p load_factor
   * (lowest_eigenpairs()) into @p directory:
   *  - modes.csv: one row per mode, its number (from 1) and eigenvalue;
   *  - if @p write_vtu, modes-NNNNN.vtu and modes.pvd: mode k drawn as the
   *    state moved along its eigenvector by a tenth of the model size
   *    (Model::length_scale()) in its largest component, the .pvd's
   *    "time" being k: ParaView steps through the modes.
   * Returns the names of the files written ("modes.csv", "modes.pvd").
   * Throws std::runtime_error where the eigen-solver fails or a file
   * cannot be written.
   */
  std::vector<std::string>
  write_mode_shapes(const RodModel    &model,
                    const VectorType  &u,
                    double             load_factor,
                    unsigned int       count,
                    const std::string &directory,
                    bool               write_vtu);
} // namespace rodnet

#endif
