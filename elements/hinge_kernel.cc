#include <elements/classic_hinge.h>
#include <elements/hinge_kernel.h>
#include <elements/simple_hinge.h>

#include <stdexcept>

namespace rodnet
{
  std::unique_ptr<HingeKernel>
  create_hinge_kernel(const std::string &name)
  {
    if (name == "simple")
      return std::make_unique<SimpleHinge>();
    if (name == "classic")
      return std::make_unique<ClassicHinge>();

    std::string known;
    for (const std::string &n : hinge_kernel_names())
      known += (known.empty() ? "\"" : ", \"") + n + "\"";
    throw std::invalid_argument("unknown hinge kernel \"" + name +
                                "\"; known kernels: " + known);
  }


  std::vector<std::string>
  hinge_kernel_names()
  {
    return {"simple", "classic"};
  }
} // namespace rodnet
