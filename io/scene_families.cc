#include <io/scene_families.h>

namespace rodnet
{
  void
  declare_element_family_parameters(dealii::ParameterHandler &prm)
  {
    const Registry<FamilyRequest> &registry = element_family_registry();
    for (const std::string &name : registry.names())
      {
        prm.enter_subsection(name);
        registry.create(name)->declare_parameters(prm);
        prm.leave_subsection();
      }
  }


  std::vector<RequestedFamily>
  parse_element_family_requests(dealii::ParameterHandler &prm)
  {
    const Registry<FamilyRequest> &registry = element_family_registry();
    std::vector<RequestedFamily>   requests;
    for (const std::string &name : registry.names())
      {
        std::shared_ptr<FamilyRequest> request = registry.create(name);
        prm.enter_subsection(name);
        request->parse_parameters(prm);
        prm.leave_subsection();
        if (request->requested())
          requests.push_back({name, std::move(request)});
      }
    return requests;
  }
} // namespace rodnet
