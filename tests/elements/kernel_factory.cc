// The hinge kernel factory: known names create the right kernel, an unknown
// name fails with a message that lists the known ones.

#include <elements/hinge_kernel.h>

#include <gtest/gtest.h>
#include <stdexcept>

namespace
{
  using namespace rodnet;

  TEST(KernelFactory, CreatesKnownKernels)
  {
    const std::vector<std::string> names = hinge_kernel_names();
    EXPECT_EQ(names, (std::vector<std::string>{"classic", "simple"}));
    for (const std::string &name : names)
      EXPECT_EQ(create_hinge_kernel(name)->name(), name);
  }

  TEST(KernelFactory, UnknownNameListsKnownNames)
  {
    try
      {
        create_hinge_kernel("bergou");
        FAIL() << "no exception for an unknown kernel name";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("bergou"), std::string::npos) << message;
        for (const std::string &name : hinge_kernel_names())
          EXPECT_NE(message.find('"' + name + '"'), std::string::npos)
            << message;
      }
  }
} // namespace
