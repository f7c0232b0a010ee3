// The scene entry "Loads/Rigid bodies": its items and where they sit on a
// network (doc/dynamics.md, "Rigid bodies").
#include <deal.II/base/utilities.h>

#include <core/vertex_selector.h>
#include <io/rigid_body_entries.h>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    const std::string syntax =
      "\"<place>: mass <m> [inertia <j> | <J_t>,<J_p> | "
      "<J_xx>,<J_yy>,<J_zz>[,<J_yz>,<J_zx>,<J_xy>]] [offset <c> | centre "
      "<dx>,<dy>,<dz>]\"";

    /// @p text as a number, NaN unless all of it is one.
    double
    number(const std::string &text)
    {
      std::size_t used  = 0;
      double      value = std::nan("");
      try
        {
          value = std::stod(text, &used);
        }
      catch (const std::exception &)
        {
        }
      return used == text.size() ? value : std::nan("");
    }

    /// The positive finite number @p text, the value of @p word of @p item.
    double
    positive(const std::string   &text,
             const std::string   &word,
             const RigidBodyItem &item)
    {
      const double value = number(text);
      if (!(value > 0) || !std::isfinite(value))
        throw std::invalid_argument(
          item.where + ": the " + word + " \"" + text +
          "\" must be a positive number" +
          (word == "offset" ? " (the centre lies beyond the rod end; leave "
                              "the offset out for a centre at the end)" :
                              ""));
      return value;
    }

    /// The finite number @p text, an off-diagonal component of the inertia
    /// tensor of @p item.
    double
    finite(const std::string &text, const RigidBodyItem &item)
    {
      const double value = number(text);
      if (!std::isfinite(value))
        throw std::invalid_argument(item.where + ": the inertia component \"" +
                                    text + "\" must be a finite number");
      return value;
    }

    /// "<J_xx>,<J_yy>,<J_zz>[,<J_yz>,<J_zx>,<J_xy>]" into @p item.
    void
    read_inertia_tensor(const std::vector<std::string> &values,
                        RigidBodyItem                  &item)
    {
      Matrix3 &J = item.inertia_tensor;
      for (unsigned int c = 0; c < 3; ++c)
        J(c, c) = positive(values[c], "inertia", item);
      if (values.size() == 6)
        for (unsigned int c = 0; c < 3; ++c)
          {
            // J_yz, J_zx, J_xy: the component off the axis c.
            const unsigned int a = (c + 1) % 3, b = (c + 2) % 3;
            J(a, b) = J(b, a) = finite(values[3 + c], item);
          }
    }

    /// "<dx>,<dy>,<dz>", the centre's offset from the vertex, into @p item.
    void
    read_centre(const std::string &text, RigidBodyItem &item)
    {
      const auto values = dealii::Utilities::split_string_list(text, ',');
      Vector3   &r      = item.centre_offset;
      for (unsigned int c = 0; c < 3 && values.size() == 3; ++c)
        r[c] = number(values[c]);
      if (values.size() != 3 || !r.allFinite() || r == Vector3::Zero())
        throw std::invalid_argument(
          item.where + ": the centre \"" + text +
          "\" must be three finite numbers <dx>,<dy>,<dz> (m), not all zero "
          "(leave it out for a centre at the vertex)");
    }

    /// "<J_t>,<J_p>", "<j>" or a tensor into @p item.
    void
    read_inertia(const std::string &text, RigidBodyItem &item)
    {
      const auto values = dealii::Utilities::split_string_list(text, ',');
      if (values.size() == 3 || values.size() == 6)
        return read_inertia_tensor(values, item);
      if (values.size() > 2 || values.empty())
        throw std::invalid_argument(
          item.where + ": the inertia \"" + text +
          "\" should be <j> (isotropic), <J_t>,<J_p> (axisymmetric about a "
          "rod end's tangent), or three or six components of a tensor");
      item.axial_inertia      = positive(values.front(), "inertia", item);
      item.transverse_inertia = positive(values.back(), "inertia", item);
      item.axisymmetric       = values.size() == 2;
    }

    /// The free end of an open rod at vertex @p v, where no junction is.
    std::optional<RodEnd>
    free_rod_end(const RodNetwork &network, const unsigned int v)
    {
      if (network.junction_at(v))
        return std::nullopt;
      for (unsigned int r = 0; r < network.rods().size(); ++r)
        {
          const Rod &rod = network.rods()[r];
          if (!rod.closed &&
              (v == rod.vertices.front() || v == rod.vertices.back()))
            return RodEnd{r, v == rod.vertices.front()};
        }
      return std::nullopt;
    }
  } // namespace

  RigidBodyItem
  parse_rigid_body_item(const std::string &place,
                        const std::string &text,
                        const std::string &entry)
  {
    RigidBodyItem item;
    item.place = place;
    item.entry = entry;
    item.where = "entry \"" + entry + "\": \"" + place + "\"";
    std::istringstream    words(text);
    std::string           word, value;
    std::set<std::string> given;
    while (words >> word)
      {
        if (word != "mass" && word != "inertia" && word != "offset" &&
            word != "centre")
          throw std::invalid_argument(item.where + ": \"" + word +
                                      "\" is none of mass, inertia, offset, "
                                      "centre; write " +
                                      syntax);
        const bool repeated = !given.insert(word).second;
        if (repeated || !(words >> value))
          throw std::invalid_argument(
            item.where + ": \"" + word + "\" " +
            (repeated ? "is given twice" : "has no value") + "; write " +
            syntax);
        if (word == "mass")
          item.mass = positive(value, word, item);
        else if (word == "offset")
          item.offset = positive(value, word, item);
        else if (word == "centre")
          read_centre(value, item);
        else
          read_inertia(value, item);
      }
    if (item.mass == 0)
      throw std::invalid_argument(item.where +
                                  ": the body has no mass; write " + syntax);
    return item;
  }

  std::optional<unsigned int>
  rigid_body_handle_vertex(const RodNetwork &network, const RigidBodyItem &item)
  {
    if (item.axial_inertia == 0 && item.inertia_tensor == Matrix3::Zero() &&
        item.centre_offset == Vector3::Zero())
      return std::nullopt;
    // At a free rod end an isotropic inertia without offset turns with a
    // handle: its ghost segment has the tangent at the end itself, where
    // the end segment's sits l/2 inside (second against first order).
    const unsigned int v = select_vertex(network, item.place, item.entry);
    if (network.junction_at(v) ||
        (free_rod_end(network, v) && (item.axisymmetric || item.offset > 0)))
      return std::nullopt;
    return v;
  }

  RigidBody
  place_rigid_body(const RodNetwork &network, const RigidBodyItem &item)
  {
    RigidBody body{item.where,
                   select_vertex(network, item.place, item.entry),
                   item.mass,
                   item.axial_inertia,
                   item.transverse_inertia,
                   item.offset};
    body.inertia_tensor  = item.inertia_tensor;
    body.centre_offset   = item.centre_offset;
    const unsigned int v = std::get<unsigned int>(body.attachment);
    if (const std::optional<RodEnd> end = free_rod_end(network, v))
      {
        body.attachment = *end;
        return body;
      }
    // A tensor with an offset: check_rigid_body() says why not.
    if ((item.offset > 0 || item.axisymmetric) && !body.has_inertia_tensor())
      {
        const auto        junction = network.junction_at(v);
        const std::string at =
          junction ?
            "the junction \"" + network.junctions()[*junction].name + "\"" :
            network.describe_vertex(v);
        throw std::invalid_argument(
          item.where + ": " + at + " is no free rod end, and " +
          (item.offset > 0 ? "an offset needs" : "two inertias J_t,J_p need") +
          " the end's tangent to align with; give the isotropic \"inertia "
          "<j>\" alone there");
      }
    if (const auto junction = network.junction_at(v))
      body.attachment = network.junctions()[*junction].vertex;
    return body;
  }
} // namespace rodnet
