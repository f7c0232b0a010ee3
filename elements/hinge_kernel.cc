#include <elements/hinge_kernel.h>

namespace rodnet
{
  Registry<HingeKernel> &
  hinge_kernel_registry()
  {
    // Built on first use, before any registration of another translation
    // unit can reach it.
    static Registry<HingeKernel> registry("hinge kernel", "kernels");
    return registry;
  }


  std::unique_ptr<HingeKernel>
  create_hinge_kernel(const std::string &name)
  {
    return hinge_kernel_registry().create(name);
  }


  std::vector<std::string>
  hinge_kernel_names()
  {
    return hinge_kernel_registry().names();
  }
} // namespace rodnet
