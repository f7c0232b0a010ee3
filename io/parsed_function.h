#ifndef RODNET_IO_PARSED_FUNCTION_H
#define RODNET_IO_PARSED_FUNCTION_H

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <io/scene.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  /// Holds std::cerr's output while it lives: deal.II writes muparser's
  /// diagnosis of an expression there before it throws, and the entry's
  /// message must say it once, on one line.
  class MutedStandardError
  {
  public:
    MutedStandardError()
        : saved(std::cerr.rdbuf(held.rdbuf()))
    {
    }
    ~MutedStandardError()
    {
      std::cerr.rdbuf(saved);
    }
    MutedStandardError(const MutedStandardError &) = delete;
    MutedStandardError &
    operator=(const MutedStandardError &) = delete;

  private:
    std::ostringstream held;
    std::streambuf    *saved;
  };

  /**
   * The function of the muparser expressions @p expressions (one per
   * component) in the variables @p variables, with the constant pi.
   * Muparser reads an expression when it is first evaluated, so every
   * component is evaluated once at the origin here, which makes a syntax
   * error or an unknown name an error of the entry @p entry (quoting its
   * text @p text) rather than of the run.
   */
  template <int dim>
  std::shared_ptr<const dealii::FunctionParser<dim>>
  parse_function(const std::vector<std::string> &expressions,
                 const std::string              &text,
                 const std::string              &variables,
                 const std::string              &entry)
  {
    auto function =
      std::make_shared<dealii::FunctionParser<dim>>(expressions.size());
    try
      {
        const MutedStandardError muted;
        function->initialize(variables, expressions, {{"pi", M_PI}});
        for (unsigned int c = 0; c < expressions.size(); ++c)
          function->value(dealii::Point<dim>(), c);
      }
    catch (const std::exception &e)
      {
        throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                    "\" is not an expression of " + variables +
                                    ": " + error_message(e));
      }
    return function;
  }

  /// parse_function() of the ';'-separated expressions @p text, which must
  /// be @p n_components of them.
  template <int dim>
  std::shared_ptr<const dealii::FunctionParser<dim>>
  parse_function(const std::string &text,
                 const std::string &variables,
                 const unsigned int n_components,
                 const std::string &entry)
  {
    const std::vector<std::string> expressions =
      dealii::Utilities::split_string_list(text, ';');
    if (expressions.size() != n_components)
      throw std::invalid_argument(
        "entry \"" + entry + "\": \"" + text + "\" should be " +
        std::to_string(n_components) + " expression(s) of " + variables +
        " separated by ';'");
    return parse_function<dim>(expressions, text, variables, entry);
  }
} // namespace rodnet

#endif
