#include <core/family_request.h>

namespace rodnet
{
  Registry<FamilyRequest> &
  element_family_registry()
  {
    // Built on first use, before any registration can reach it.
    static Registry<FamilyRequest> registry("element family",
                                            "element families");
    return registry;
  }
} // namespace rodnet
