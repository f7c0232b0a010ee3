#ifndef RODNET_IO_SCENE_FAMILIES_H
#define RODNET_IO_SCENE_FAMILIES_H

#include <deal.II/base/parameter_handler.h>

#include <core/family_request.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /// Declares the subsection of every registered element family
  /// (element_family_registry()), named after it, with its entries.
  void
  declare_element_family_parameters(dealii::ParameterHandler &prm);

  /// A family a scene asks for: its subsection and its parsed entries.
  struct RequestedFamily
  {
    std::string                          name;
    std::shared_ptr<const FamilyRequest> request;
  };

  /// Reads every registered family's subsection; returns the families the
  /// scene asks for (FamilyRequest::requested()). Throws
  /// std::invalid_argument naming the entry for an inadmissible value.
  std::vector<RequestedFamily>
  parse_element_family_requests(dealii::ParameterHandler &prm);
} // namespace rodnet

#endif
