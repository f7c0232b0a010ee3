#ifndef RODNET_CORE_ACTIVATION_FIELD_H
#define RODNET_CORE_ACTIVATION_FIELD_H

#include <Eigen/Core>
#include <functional>
#include <memory>

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

  /**
   * What scales an activation field (doc/morphing.md): nothing (fixed, at
   * its full value throughout), the load factor (ramped: load stepping,
   * continuation's parameter, time stepping's "Load factor"), or a function
   * of time of its own (time stepping: RodModel::set_time()).
   */
  struct ActivationDrive
  {
    enum class Kind
    {
      fixed,
      load_factor,
      time
    } kind = Kind::load_factor;
    /// Kind::time: the factor at time t (s); it throws where it has none.
    /// Fields driven by one object share their storage.
    std::shared_ptr<const std::function<double(double)>> of_time;
  };
} // namespace rodnet

#endif
