// The families every RodModel adds by itself: a new built-in family adds
// its line to the list below (its order is that of the declared blocks).
#include <core/built_in_families.h>
#include <families/developable_ribbon_family.h>
#include <families/hinge_family.h>
#include <families/inextensibility_family.h>
#include <families/junction_family.h>
#include <families/stretch_family.h>

namespace rodnet
{
  namespace
  {
    std::unique_ptr<ElementFamily>
    hinges(const ModelParts &parts)
    {
      return std::make_unique<HingeFamily>(parts.layout,
                                           parts.hinge_kernels,
                                           parts.materials);
    }

    std::unique_ptr<ElementFamily>
    junction_elements(const ModelParts &parts)
    {
      return std::make_unique<JunctionFamily>(parts.layout,
                                              parts.network,
                                              parts.junction_kernels,
                                              parts.materials);
    }

    std::unique_ptr<ElementFamily>
    stretching(const ModelParts &parts)
    {
      return std::make_unique<StretchFamily>(parts.layout,
                                             parts.network,
                                             parts.materials);
    }

    std::unique_ptr<ElementFamily>
    inextensibility(const ModelParts &parts)
    {
      if (!InextensibilityFamily::applies_to(parts.network))
        return nullptr;
      return std::make_unique<InextensibilityFamily>(parts.layout,
                                                     parts.network,
                                                     parts.configuration,
                                                     parts.materials);
    }

    std::unique_ptr<ElementFamily>
    developable_ribbons(const ModelParts &parts)
    {
      if (!DevelopableRibbonFamily::applies_to(parts.network))
        return nullptr;
      return std::make_unique<DevelopableRibbonFamily>(parts.layout,
                                                       parts.network,
                                                       parts.configuration,
                                                       parts.hinge_kernels,
                                                       parts.materials);
    }
  } // namespace

  const BuiltInFamilyRegistry &
  built_in_family_registry()
  {
    static const BuiltInFamilyRegistry registry = [] {
      BuiltInFamilyRegistry r("built-in family",
                              "built-in families",
                              RegistryOrder::registration);
      r.add("hinges", "bending and twisting at every hinge", hinges);
      r.add("junction elements",
            "bending and twisting at junctions; the junctions' quaternions",
            junction_elements);
      r.add("segments", "stretching of every extensible segment", stretching);
      r.add("inextensibility",
            "a multiplier per segment of every inextensible rod",
            inextensibility);
      r.add("developable ribbons",
            "the Wunderlich energy and the developability of ribbons",
            developable_ribbons);
      return r;
    }();
    return registry;
  }
} // namespace rodnet
