#ifndef RODNET_CORE_BUILT_IN_FAMILIES_H
#define RODNET_CORE_BUILT_IN_FAMILIES_H

#include <base/registry.h>
#include <core/configuration.h>
#include <core/dof_layout.h>
#include <core/element_family.h>
#include <core/rod_network.h>
#include <elements/hinge_kernel.h>
#include <elements/junction_kernel.h>
#include <materials/rod_material.h>

#include <memory>
#include <vector>

namespace rodnet
{
  /// The parts of a RodModel that its built-in families are made of (all
  /// outlive the families).
  struct ModelParts
  {
    const DofLayout     &layout;
    const RodNetwork    &network;
    const Configuration &configuration;
    /// Per rod: the hinge kernel and the junction kernel.
    const std::vector<std::unique_ptr<HingeKernel>>       &hinge_kernels;
    const std::vector<std::unique_ptr<JunctionKernel>>    &junction_kernels;
    const std::vector<std::shared_ptr<const RodMaterial>> &materials;
  };

  /**
   * The element families a RodModel adds by itself, through
   * add_element_family() like any family: one loop over this registry, in
   * its order, which is also the order of their declared DoF blocks (the
   * junctions' quaternions, then the inextensibility multipliers, then the
   * ribbons' DoFs). A factory returns nullptr where the network does not ask
   * for its family (no inextensible rod, no ribbon): a scene pays only for
   * what it uses. Filled from one explicit list in
   * families/built_in_families.cc; a family that a scene or a user asks for
   * is registered as a FamilyRequest instead (core/family_request.h).
   */
  using BuiltInFamilyRegistry = Registry<ElementFamily, const ModelParts &>;

  /// The one registry of built-in families.
  const BuiltInFamilyRegistry &
  built_in_family_registry();
} // namespace rodnet

#endif
