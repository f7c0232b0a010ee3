#include <materials/rod_material.h>

#include <stdexcept>

namespace rodnet
{
  MaterialRegistry &
  MaterialRegistry::instance()
  {
    // A function-local static is built on first use, so registrations from
    // static objects in other translation units cannot run before it exists.
    static MaterialRegistry registry;
    return registry;
  }

  std::shared_ptr<const RodMaterial>
  RodMaterial::with_natural_shape_scaled(const NaturalShapeParts &,
                                         double) const
  {
    throw std::invalid_argument(
      "the material has no natural shape to ramp (only the linear elastic "
      "rod has natural curvatures, twist and eigenstrain)");
  }
} // namespace rodnet
