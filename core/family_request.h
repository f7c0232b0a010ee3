#ifndef RODNET_CORE_FAMILY_REQUEST_H
#define RODNET_CORE_FAMILY_REQUEST_H

#include <deal.II/base/parameter_handler.h>

#include <base/registry.h>
#include <core/element_family.h>

#include <memory>

namespace rodnet
{
  class RodModel;

  /**
   * An element family that a scene can ask for: the entries it reads from
   * the scene subsection named after it, and the family it adds to a model.
   * Registered by name in element_family_registry() with one
   * RODNET_REGISTER_ELEMENT_FAMILY line in the family's own .cc file; the
   * scene declares and reads the entries of every registered family and
   * adds those that are requested (doc/architecture.md).
   */
  class FamilyRequest
  {
  public:
    virtual ~FamilyRequest() = default;

    /// Declares the family's entries in the current subsection.
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /// Reads them; throws std::invalid_argument naming the entry (relative
    /// to the subsection) for an inadmissible value.
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;

    /// Whether the entries ask for the family: a scene pays only for the
    /// families it uses.
    virtual bool
    requested() const = 0;

    /// The family on @p model (not yet finalized); throws
    /// std::invalid_argument where the entries do not fit the model.
    virtual std::unique_ptr<ElementFamily>
    create(const RodModel &model) const = 0;
  };

  /// The families a scene can ask for, by the name of their subsection.
  Registry<FamilyRequest> &
  element_family_registry();
} // namespace rodnet

/// Registers FamilyRequest class @p classname (unqualified, inside
/// namespace rodnet) under the scene subsection @p name.
#define RODNET_REGISTER_ELEMENT_FAMILY(classname, name, description)      \
  namespace                                                               \
  {                                                                       \
    const bool rodnet_registered_##classname = [] {                       \
      rodnet::element_family_registry().add(name, description, [] {       \
        return std::unique_ptr<rodnet::FamilyRequest>(new classname());   \
      });                                                                 \
      return true;                                                        \
    }();                                                                  \
  }

#endif
