#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <io/activation_fields.h>
#include <io/parsed_function.h>
#include <io/rod_groups.h>
#include <io/scene_entries.h>
#include <io/time_drive.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    using scene_entries::number;

    /// "entry "<entry>", item "<text>": ".
    std::string
    item_context(const std::string &entry, const std::string &text)
    {
      return "entry \"" + entry + "\", item \"" + text + "\": ";
    }

    /// The ','-separated parts of @p text outside parentheses (a
    /// function's arguments stay in their component).
    std::vector<std::string>
    top_level_components(const std::string &text)
    {
      std::vector<std::string> parts(1);
      int                      depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (c == ',' && depth == 0)
            parts.emplace_back();
          else
            parts.back() += c;
        }
      for (std::string &part : parts)
        part = dealii::Utilities::trim(part);
      return parts;
    }

    /// The number @p word is; none if it is not one.
    std::optional<double>
    read_number(const std::string &word)
    {
      char        *end   = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (word.empty() || *end != '\0' || !std::isfinite(value))
        return std::nullopt;
      return value;
    }

    /// Reads the region @p words (after "on") into @p item.
    void
    read_region(const std::vector<std::string> &words, ActivationItem &item)
    {
      const std::string context = item_context(item.entry, item.text);
      if (words.size() == 1 && words[0] == "all")
        return;
      if (words.size() == 3 && words[0] == "near" && words[1] == "ends")
        {
          const std::optional<double> d = read_number(words[2]);
          if (!d || !(*d > 0))
            throw std::invalid_argument(
              context + "the distance \"" + words[2] +
              "\" of \"near ends\" is not a positive number");
          item.region = ActivationItem::Region::near_ends;
          item.start  = *d;
          return;
        }
      if (words.size() == 3 && words[1] == "to")
        {
          const std::optional<double> s0 = read_number(words[0]),
                                      s1 = read_number(words[2]);
          if (!s0 || !s1 || !(*s0 >= 0) || !(*s1 > *s0))
            throw std::invalid_argument(
              context + "\"" + words[0] + " to " + words[2] +
              "\" is not an arc-length interval s0 to s1 with 0 <= s0 < s1");
          item.region = ActivationItem::Region::interval;
          item.start  = *s0;
          item.end    = *s1;
          return;
        }
      throw std::invalid_argument(
        context + "the region after \"on\" should be \"all\", \"<s0> to "
                  "<s1>\" or \"near ends <d>\"");
    }

    /// Reads the drive at the end of @p words ("fixed", "ramped", "in time
    /// <expression>") into @p item and removes it from @p words.
    void
    read_drive(std::vector<std::string> &words, ActivationItem &item)
    {
      using Kind = ActivationDrive::Kind;
      const TimeFunction in_time =
        read_in_time(words, item.entry, item_context(item.entry, item.text));
      if (in_time.given())
        {
          item.drive = {Kind::time, in_time.of_time};
          return;
        }
      if (!words.empty() &&
          (words.back() == "fixed" || words.back() == "ramped"))
        {
          item.drive.kind =
            words.back() == "fixed" ? Kind::fixed : Kind::load_factor;
          words.pop_back();
        }
    }

    /// The item @p text of @p entry: values, region, drive.
    ActivationItem
    parse_item(const std::string     &entry_name,
               const ActivationEntry &entry,
               const std::string     &text)
    {
      ActivationItem item;
      item.entry         = entry_name;
      item.text          = text;
      item.first_density = entry.first_density;
      std::vector<std::string> words =
        dealii::Utilities::split_string_list(text, ' ');
      read_drive(words, item);
      const auto on = std::find(words.begin(), words.end(), "on");
      if (on != words.end())
        read_region(std::vector<std::string>(on + 1, words.end()), item);
      std::string values;
      for (auto w = words.begin(); w != on; ++w)
        values += (values.empty() ? "" : " ") + *w;
      const std::vector<std::string> components = top_level_components(values);
      if (components.size() != entry.n_densities ||
          std::count(components.begin(), components.end(), "") > 0)
        throw std::invalid_argument(
          item_context(entry_name, text) + "give " +
          (entry.n_densities == 1 ?
             std::string("one value") :
             std::to_string(entry.n_densities) + " values separated by ','") +
          " (numbers or expressions of s and L), then optionally \"on "
          "<region>\" and \"fixed\" or \"in time <expression of t>\"");
      item.values = parse_function<2>(components, values, "s,L", entry_name);
      return item;
    }

    /// The arc-length intervals of the region of @p item on a rod of
    /// length @p length.
    std::vector<std::pair<double, double>>
    region_intervals(const ActivationItem &item, const double length)
    {
      switch (item.region)
        {
          case ActivationItem::Region::interval:
            return {{item.start, item.end}};
          case ActivationItem::Region::near_ends:
            {
              // Where the two end regions overlap they are the whole rod.
              const double d = std::min(item.start, 0.5 * length);
              return {{0., d}, {length - d, length}};
            }
          default:
            return {{0., length}};
        }
    }
  } // namespace

  const std::vector<ActivationEntry> &
  activation_entries()
  {
    static const std::vector<ActivationEntry> entries{
      {"Natural curvature", 0, 2},
      {"Natural twist", 2, 1},
      {"Axial eigenstrain", 3, 1}};
    return entries;
  }

  std::vector<ActivationItem>
  parse_activation_items(const std::string     &group,
                         const ActivationEntry &entry,
                         const std::string     &text)
  {
    const std::string entry_name =
      group_subsection_prefix + group + "/" + entry.name;
    std::vector<ActivationItem> items;
    for (const std::string &item :
         dealii::Utilities::split_string_list(text, ';'))
      if (!item.empty())
        items.push_back(parse_item(entry_name, entry, item));
    return items;
  }

  ActivationField
  activation_field(const ActivationItem &item,
                   const double          length,
                   const double          start_offset,
                   const std::string    &rod)
  {
    const double reach =
      item.region == ActivationItem::Region::interval ? item.end : item.start;
    // A region that ends at the rod's end, written with its digits, may
    // pass it by rounding.
    if (item.region != ActivationItem::Region::whole_rod &&
        reach > length * (1 + 1e-12))
      throw std::invalid_argument(item_context(item.entry, item.text) +
                                  "the region reaches s = " + number(reach) +
                                  ", past the end of " + rod + " (length " +
                                  number(length) + ")");
    const std::vector<std::pair<double, double>> region =
      region_intervals(item, length);
    return [item, region, length, start_offset, rod](const double t0,
                                                     const double t1) {
      static const dealii::QGauss<1> gauss(3);
      Eigen::Vector4d                integral = Eigen::Vector4d::Zero();
      const auto value = [&](const double s, const unsigned int c) {
        const double v = item.values->value(dealii::Point<2>(s, length), c);
        if (!std::isfinite(v))
          throw std::invalid_argument(
            item_context(item.entry, item.text) + "the value is " + number(v) +
            " at s = " + number(s) + " of " + rod +
            "; give values finite on the whole region");
        return v;
      };
      for (const auto &[a, b] : region)
        {
          const double c = std::max(a, t0 - start_offset),
                       d = std::min(b, t1 - start_offset);
          if (!(d > c))
            continue;
          const unsigned int n = item.values->n_components;
          for (unsigned int k = 0; k < n; ++k)
            {
              // The ends are the vertices the field is checked at.
              value(c, k);
              value(d, k);
              for (unsigned int q = 0; q < gauss.size(); ++q)
                integral[item.first_density + k] +=
                  (d - c) * gauss.weight(q) *
                  value(c + (d - c) * gauss.point(q)[0], k);
            }
        }
      return integral;
    };
  }
} // namespace rodnet
