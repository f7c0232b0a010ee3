#ifndef RODNET_IO_ACTIVATION_FIELDS_H
#define RODNET_IO_ACTIVATION_FIELDS_H

#include <deal.II/base/function_parser.h>

#include <core/activation_field.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * One item of an activation entry of a group subsection
   * (doc/morphing.md, "Activation fields"): values, constants or muparser
   * expressions of the arc length s and the rod's length L, on a region of
   * each rod of the group, ramped with the load factor, held fixed, or
   * scaled by an expression of the time t (time stepping):
   *
   *   <values> [on all | on <s0> to <s1> | on near ends <d>]
   *            [fixed | ramped | in time <expression of t>]
   */
  struct ActivationItem
  {
    /// The entry ("Group x-beams/Natural curvature") and the item as
    /// written, for messages.
    std::string entry, text;
    /// The first density it gives (0: kappa_1, 1: kappa_2, 2: twist rate,
    /// 3: axial eigenstrain), one per component of values.
    unsigned int first_density = 0;
    /// The values as a function of (s, L), one component per density.
    std::shared_ptr<const dealii::FunctionParser<2>> values;
    enum class Region
    {
      whole_rod,
      interval, ///< [start, end]
      near_ends ///< within @p start of either end
    } region     = Region::whole_rod;
    double start = 0., end = 0.;
    /// Scaled by the load factor (the default), held fixed, or scaled by
    /// its function of time, which throws naming the entry, the item and
    /// the time where it is not finite.
    ActivationDrive drive;
  };

  /// An activation entry of the group subsections: its name, the first
  /// density it gives and how many.
  struct ActivationEntry
  {
    const char  *name;
    unsigned int first_density, n_densities;
  };

  /// "Natural curvature" (kappa_1, kappa_2), "Natural twist", "Axial
  /// eigenstrain".
  const std::vector<ActivationEntry> &
  activation_entries();

  /**
   * The ';'-separated items of the entry @p entry of subsection
   * "Group <group>" with text @p text (empty: none). Throws
   * std::invalid_argument naming the entry and the item for a malformed
   * item: a wrong number of values, an expression muparser cannot read
   * (values or time function), a region that is not one of the three
   * forms, an empty interval or a distance not positive.
   */
  std::vector<ActivationItem>
  parse_activation_items(const std::string     &group,
                         const ActivationEntry &entry,
                         const std::string     &text);

  /**
   * The activation field of @p item on a rod of length @p length whose
   * polygon starts at arc length -@p start_offset (half a segment behind
   * the start under a midpoint clamp), for RodModel::add_activation().
   * Throws std::invalid_argument naming the entry, the item and @p rod
   * where the region reaches past the rod's length; the field throws, with
   * the arc length, where the values are not finite (at every vertex and
   * quadrature point of the region).
   */
  ActivationField
  activation_field(const ActivationItem &item,
                   double                length,
                   double                start_offset,
                   const std::string    &rod);
} // namespace rodnet

#endif
