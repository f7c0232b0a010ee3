#include <materials/rod_material.h>

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
} // namespace rodnet
