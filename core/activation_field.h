#ifndef RODNET_CORE_ACTIVATION_FIELD_H
#define RODNET_CORE_ACTIVATION_FIELD_H

#include <Eigen/Core>
#include <functional>

namespace rodnet
{
  /**
   * An activation field of one rod (doc/morphing.md, "Activation fields"):
   * the integral over the arc-length interval [t0, t1] of its densities
   * (natural curvature about d1, about d2, natural twist rate, axial
   * eigenstrain), t the undeformed length along the rod's polygon from its
   * first vertex. The model integrates it over each hinge's Voronoi cell,
   * each junction element's half segment and each segment
   * (Configuration::add_activation()).
   */
  using ActivationField = std::function<Eigen::Vector4d(double t0, double t1)>;
} // namespace rodnet

#endif
