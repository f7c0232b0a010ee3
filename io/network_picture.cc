#include <deal.II/base/mpi.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <io/gnuplot.h>
#include <io/network_picture.h>
#include <io/picture_camera.h>
#include <io/picture_fields.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace rodnet
{
  namespace
  {
    using Point2 = std::array<double, 2>;

    /// A rod as drawn: its polyline before and after the deformation (in
    /// screen coordinates), the value of the field on each piece of the
    /// deformed one (that of the piece ending at point k is values[k],
    /// gnuplot's rule) and its mean depth.
    struct DrawnRod
    {
      std::vector<Point2> undeformed, deformed;
      std::vector<double> values;
      double              depth = 0;
    };

    /**
     * The value of the vertex field @p field that colours the half
     * segments next to vertex @p j of @p rod: its own, but where the field
     * is defined at interior vertices only (curvature: at hinges), at the
     * ends of an open rod of two or more segments that of the vertex next
     * to it; the end's 0 would draw every junction of a network as a spot
     * of zero.
     */
    double
    vertex_value(const Rod &rod, const PictureField &field, unsigned int j)
    {
      const unsigned int n = rod.segments.size();
      if (field.interior_vertices_only && !rod.closed && n >= 2)
        j = std::clamp(j, 1u, n - 1);
      return field.values[rod.vertices[j % rod.vertices.size()]];
    }

    /**
     * The rods of @p network projected by @p camera, coloured by @p field.
     * A segment field colours its segment; a vertex field the half of
     * each segment next to the vertex (a point at the segment's middle
     * splits it; vertex_value()), so that no value is averaged away.
     * Closed rods come back to their first vertex.
     */
    std::vector<DrawnRod>
    drawn_rods(const RodNetwork    &network,
               const PictureState  &state,
               const PictureField  &field,
               const PictureCamera &camera)
    {
      const auto screen = [&](const Vector3 &p) {
        const auto xyz = camera.project(p);
        return Point2{{xyz[0], xyz[1]}};
      };
      std::vector<DrawnRod> rods;
      for (const Rod &rod : network.rods())
        {
          DrawnRod           drawn;
          const unsigned int n = rod.segments.size();
          for (unsigned int j = 0; j <= n; ++j)
            {
              const unsigned int v  = rod.vertices[j % rod.vertices.size()];
              const Vector3     &x  = state.positions[v];
              const Vector3     &x0 = network.vertex(v);
              drawn.undeformed.push_back(screen(x0));
              drawn.depth += camera.project(x)[2] / (n + 1);
              if (field.per_segment)
                {
                  drawn.deformed.push_back(screen(x));
                  drawn.values.push_back(
                    field.values[rod.segments[j == 0 ? 0 : j - 1]]);
                  continue;
                }
              if (j > 0)
                {
                  const unsigned int before =
                    rod.vertices[(j - 1) % rod.vertices.size()];
                  drawn.deformed.push_back(
                    screen(0.5 * (x + state.positions[before])));
                  drawn.values.push_back(vertex_value(rod, field, j - 1));
                }
              drawn.deformed.push_back(screen(x));
              drawn.values.push_back(vertex_value(rod, field, j));
            }
          rods.push_back(std::move(drawn));
        }
      // The farthest first: nearer rods are drawn over them.
      std::stable_sort(rods.begin(),
                       rods.end(),
                       [](const DrawnRod &a, const DrawnRod &b) {
                         return a.depth < b.depth;
                       });
      return rods;
    }

    /**
     * The frame of a picture: the range of screen coordinates it shows
     * (every point of both shapes, with a margin of 4 % of the larger
     * extent), widened so that its aspect is that of the drawing area,
     * and that area's size in pixels: @p size along its longer side, at
     * least 240 along the other (room for the colour bar).
     */
    struct PictureFrame
    {
      PictureFrame(const std::vector<DrawnRod> &rods, unsigned int size);

      /// The middle of the range: the script's coordinates are written
      /// from it, so that a structure far from the origin keeps its
      /// digits.
      Point2
      centre() const
      {
        return {{0.5 * (low[0] + high[0]), 0.5 * (low[1] + high[1])}};
      }

      std::array<double, 2> low{}, high{};
      unsigned int          width = 0, height = 0;
      /// Pixels per unit of screen coordinates.
      double scale = 1;
    };

    PictureFrame::PictureFrame(const std::vector<DrawnRod> &rods,
                               const unsigned int           size)
    {
      low  = {{INFINITY, INFINITY}};
      high = {{-INFINITY, -INFINITY}};
      for (const DrawnRod &rod : rods)
        for (const auto *line : {&rod.undeformed, &rod.deformed})
          for (const Point2 &p : *line)
            for (unsigned int c = 0; c < 2; ++c)
              if (std::isfinite(p[c]))
                {
                  low[c]  = std::min(low[c], p[c]);
                  high[c] = std::max(high[c], p[c]);
                }
      if (!(low[0] <= high[0] && low[1] <= high[1]))
        low = {{-1, -1}}, high = {{1, 1}};
      double extent = std::max({high[0] - low[0], high[1] - low[1], 0.0});
      if (!(extent > 0))
        extent = 1;
      const double          margin = 0.04 * extent;
      std::array<double, 2> span;
      for (unsigned int c = 0; c < 2; ++c)
        {
          low[c] -= margin, high[c] += margin;
          span[c] = high[c] - low[c];
        }
      const bool         wide   = span[0] >= span[1];
      const double       aspect = span[wide ? 1 : 0] / span[wide ? 0 : 1];
      const unsigned int other =
        std::max(240u, static_cast<unsigned int>(std::lround(size * aspect)));
      width  = wide ? size : other;
      height = wide ? other : size;
      // The short side grown to 240 pixels: its range grows alike.
      scale = std::min(width / span[0], height / span[1]);
      for (unsigned int c = 0; c < 2; ++c)
        {
          const double grow =
            0.5 * ((c == 0 ? width : height) / scale - span[c]);
          low[c] -= grow, high[c] += grow;
        }
    }

    /**
     * Drops the points of @p line (and their @p values, if given) that lie
     * closer than @p spacing to the point kept before them, but the last:
     * a piece shorter than a pixel or two shows nothing a reader can see
     * and costs gnuplot as much as a long one. A merged piece takes the
     * colour of its last original piece.
     */
    void
    thin_out(std::vector<Point2> &line,
             std::vector<double> *values,
             const double         spacing)
    {
      std::size_t kept = 0;
      for (std::size_t k = 1; k < line.size(); ++k)
        if (k + 1 == line.size() ||
            std::hypot(line[k][0] - line[kept][0],
                       line[k][1] - line[kept][1]) >= spacing)
          {
            line[++kept] = line[k];
            if (values != nullptr)
              (*values)[kept] = (*values)[k];
          }
      line.resize(std::min(line.size(), kept + 1));
      if (values != nullptr)
        values->resize(line.size());
    }

    /// @p value with @p digits significant digits ("NaN" if not finite).
    std::string
    picture_number(const double value, const int digits = 6)
    {
      if (!std::isfinite(value))
        return "NaN";
      char text[32];
      std::snprintf(text, sizeof(text), "%.*g", digits, value);
      return text;
    }

    /// Five colours of viridis, evenly spaced from its low end to its high
    /// end (perceptually uniform, readable in grey and by the
    /// colour-blind).
    constexpr std::array<std::array<int, 3>, 5> viridis = {
      {{{0x44, 0x01, 0x54}},
       {{0x3b, 0x52, 0x8b}},
       {{0x21, 0x91, 0x8c}},
       {{0x5e, 0xc9, 0x62}},
       {{0xfd, 0xe7, 0x25}}}};

    /// Viridis at @p t (0 to 1) as "'#rrggbb'", interpolated linearly.
    std::string
    viridis_at(const double t)
    {
      const double       x = std::clamp(t, 0.0, 1.0) * (viridis.size() - 1);
      const unsigned int k = std::min<unsigned int>(x, viridis.size() - 2);
      char               text[16];
      int                c[3];
      for (unsigned int i = 0; i < 3; ++i)
        c[i] = std::lround(viridis[k][i] +
                           (x - k) * (viridis[k + 1][i] - viridis[k][i]));
      std::snprintf(text, sizeof(text), "'#%02x%02x%02x'", c[0], c[1], c[2]);
      return text;
    }

    /// The palette: viridis, or, given @p bands (the lowest of some
    /// consecutive integers and how many they are), one band of one colour
    /// per integer (a sharp step where two colours share a position).
    std::string
    palette(const std::optional<std::pair<double, unsigned int>> &bands)
    {
      std::string text = "set palette defined (";
      if (!bands)
        for (unsigned int k = 0; k < viridis.size(); ++k)
          text += (k == 0 ? "" : ", ") + std::to_string(k) + " " +
                  viridis_at(k / (viridis.size() - 1.0));
      else
        for (unsigned int i = 0; i < bands->second; ++i)
          {
            const std::string colour =
              viridis_at(bands->second == 1 ? 0.5 : i / (bands->second - 1.0));
            const double value = bands->first + i;
            text += (i == 0 ? "" : ", ") + picture_number(value - 0.5) + " " +
                    colour + ", " + picture_number(value + 0.5) + " " + colour;
          }
      return text + ")\n";
    }

    /// The line that opens and the line that closes the colour settings
    /// of a script (with_colour_range() replaces what is between).
    const std::string colour_begin = "# colour bar\n",
                      colour_end   = "# end of colour bar\n";

    /**
     * The colour settings of a field over @p range: the palette and the
     * colour bar's range, between colour_begin and colour_end. viridis; a
     * field of at most 12 integers (rod, group, layer) in bands, one per
     * value; one constant to 1e-9 (rounding) around its value.
     */
    std::string
    colour_settings(const ColourRange &range)
    {
      double low = range.low, high = range.high;
      if (!(low <= high))
        low = 0, high = 0;
      const bool bands = range.integers && low == std::round(low) &&
                         high == std::round(high) && high - low < 12;
      std::ostringstream text;
      text << colour_begin
           << palette(bands ? std::make_optional(std::make_pair(
                                low,
                                static_cast<unsigned int>(high - low + 1))) :
                              std::nullopt);
      if (bands)
        {
          text << "set cbtics 1\n";
          low -= 0.5, high += 0.5;
        }
      else if (high - low <= 1e-9 * std::max(std::abs(low), std::abs(high)))
        {
          const double half = low == 0 ? 1 : 0.1 * std::abs(low);
          low -= half, high += half;
        }
      text << "set cbrange [" << picture_number(low, 15) << ":"
           << picture_number(high, 15) << "]\n"
           << colour_end;
      return text.str();
    }

    /// The range of the finite values of @p field.
    ColourRange
    colour_range(const PictureField &field)
    {
      ColourRange range;
      for (const double v : field.values)
        if (std::isfinite(v))
          {
            range.low      = std::min(range.low, v);
            range.high     = std::max(range.high, v);
            range.integers = range.integers && v == std::round(v);
          }
      return range;
    }

    /// The line width of the deformed rods in pixels: 0.05 of the area
    /// per pixel of line drawn, between 0.6 and 3.
    double
    line_width(const std::vector<DrawnRod> &rods, const PictureFrame &frame)
    {
      double length = 0;
      for (const DrawnRod &rod : rods)
        for (std::size_t k = 1; k < rod.deformed.size(); ++k)
          {
            const double piece =
              std::hypot(rod.deformed[k][0] - rod.deformed[k - 1][0],
                         rod.deformed[k][1] - rod.deformed[k - 1][1]);
            if (std::isfinite(piece))
              length += piece * frame.scale;
          }
      const double width =
        0.05 * frame.width * frame.height / std::max(length, 1.0);
      return std::clamp(width, 0.6, 3.0);
    }

    /// The data blocks $undeformed (x y) and $deformed (x y value), the
    /// coordinates from @p origin, a blank line between two rods.
    void
    write_picture_data(std::ostream                &script,
                       const std::vector<DrawnRod> &rods,
                       const Point2                &origin)
    {
      const auto xy = [&](const Point2 &p) {
        return picture_number(p[0] - origin[0]) + " " +
               picture_number(p[1] - origin[1]);
      };
      script << "$undeformed << EOD\n";
      for (const DrawnRod &rod : rods)
        {
          for (const Point2 &p : rod.undeformed)
            script << xy(p) << "\n";
          script << "\n";
        }
      script << "EOD\n$deformed << EOD\n";
      for (const DrawnRod &rod : rods)
        {
          for (std::size_t k = 0; k < rod.deformed.size(); ++k)
            script << xy(rod.deformed[k]) << " "
                   << picture_number(rod.values[k]) << "\n";
          script << "\n";
        }
      script << "EOD\n";
    }

    /// The margins around a picture's drawing area in pixels: 40 above for
    /// the title, 150 at its right for the colour bar or the legend.
    constexpr double left = 20, right = 150, bottom = 20, top = 40;

    /**
     * The terminal and layout: the drawing area of @p frame's size with
     * the margins around it, the colour bar spanning 80 % of its height;
     * no axes. The coordinates are those from the frame's centre.
     */
    std::string
    layout_settings(const PictureFrame &frame,
                    const std::string  &png_path,
                    const std::string  &title)
    {
      const double width  = frame.width + left + right;
      const double height = frame.height + bottom + top;
      const int    font   = std::max(10, int(std::lround(frame.width / 90.)));
      const Point2 origin = frame.centre();
      std::ostringstream text;
      text << "set terminal pngcairo noenhanced rounded size " << width << ","
           << height << " font '," << font << "'\n"
           << "set output " << gnuplot_quote(png_path) << "\n"
           << "unset border\nunset tics\nunset key\nset cbtics\n"
           << "set lmargin at screen " << left / width << "\n"
           << "set rmargin at screen " << (left + frame.width) / width << "\n"
           << "set bmargin at screen " << bottom / height << "\n"
           << "set tmargin at screen " << (bottom + frame.height) / height
           << "\n"
           << "set xrange [" << picture_number(frame.low[0] - origin[0], 15)
           << ":" << picture_number(frame.high[0] - origin[0], 15) << "]\n"
           << "set yrange [" << picture_number(frame.low[1] - origin[1], 15)
           << ":" << picture_number(frame.high[1] - origin[1], 15) << "]\n"
           << "set size ratio -1\n"
           << "set colorbox vertical user origin screen "
           << (left + frame.width + 20) / width << ", screen "
           << (bottom + 0.1 * frame.height) / height << " size screen "
           << 18 / width << ", screen " << 0.8 * frame.height / height << "\n"
           << "set label 1 " << gnuplot_quote(title) << " at screen "
           << left / width << ", screen " << 1 - 0.5 * top / height
           << " left\n";
      return text.str();
    }

    /// The colours of the categories of a field ("group"), in order: Okabe
    /// and Ito's palette, told apart by the colour-blind, none of them
    /// grey; and the neutral grey of the rods in no category.
    constexpr std::array<const char *, max_picture_groups> category_colours = {
      {"#0072b2",
       "#d55e00",
       "#009e73",
       "#cc79a7",
       "#e69f00",
       "#56b4e9",
       "#f0e442"}};
    constexpr const char *no_category_colour = "#808080";

    /**
     * The settings that draw a field of the categories @p categories: no
     * colour bar, the legend in its place (top left of the right margin
     * of @p frame, titled @p heading) and the function category_colour(k)
     * that gives the colour of category k (the data's third column; -1:
     * none) as gnuplot's "linecolor rgb variable" reads it.
     */
    std::string
    category_settings(const PictureFrame             &frame,
                      const std::vector<std::string> &categories,
                      const std::string              &heading)
    {
      if (categories.size() > category_colours.size())
        throw std::invalid_argument(
          "network_picture_script: " + std::to_string(categories.size()) +
          " categories, more than the palette's colours");
      const double       width  = frame.width + left + right;
      const double       height = frame.height + bottom + top;
      std::ostringstream text;
      text << "unset colorbox\n"
           << "set key at screen " << (left + frame.width + 10) / width
           << ", screen " << (bottom + 0.9 * frame.height) / height
           << " left top Left reverse samplen 2 noautotitle title "
           << gnuplot_quote(heading) << "\n"
           << "category_colour(k) = ";
      // "#rrggbb" as the number 0xrrggbb.
      const auto number = [](const char *colour) {
        return "0x" + std::string(colour).substr(1);
      };
      for (std::size_t k = 0; k < categories.size(); ++k)
        text << "k == " << k << " ? " << number(category_colours[k]) << " : ";
      text << number(no_category_colour) << "\n";
      return text.str();
    }

    /// Gives the pieces of @p rods in no category (NaN, which would break
    /// their lines) the value -1; returns whether there are any.
    bool
    mark_no_category(std::vector<DrawnRod> &rods)
    {
      bool any = false;
      for (DrawnRod &rod : rods)
        for (double &value : rod.values)
          if (!std::isfinite(value))
            value = -1, any = true;
      return any;
    }

    /// The legend's entries of @p categories, and of none where
    /// @p with_none (a rod in no category), as clauses of the plot command.
    std::string
    category_legend(const std::vector<std::string> &categories,
                    const bool                      with_none,
                    const double                    width)
    {
      std::string clauses;
      for (std::size_t k = 0; k <= categories.size(); ++k)
        if (k < categories.size() || with_none)
          clauses +=
            ", \\\n     keyentry with lines linecolor rgb '" +
            std::string(k < categories.size() ? category_colours[k] :
                                                no_category_colour) +
            "' linewidth " + picture_number(width, 3) + " title " +
            gnuplot_quote(k < categories.size() ? categories[k] : "(other)");
      return clauses;
    }

    /// The angle @p text, the @p name of "Picture view" = @p view, in
    /// degrees within [@p low, @p high]; throws naming the entry otherwise.
    double
    angle_of_view(const std::string &view,
                  const std::string &text,
                  const std::string &name,
                  const double       low,
                  const double       high)
    {
      std::size_t used  = 0;
      double      angle = NAN;
      try
        {
          angle = std::stod(text, &used);
        }
      catch (const std::exception &)
        {
        }
      if (used != text.size() || !(angle >= low && angle <= high))
        throw std::invalid_argument(
          "entry \"Output/Picture view\": in \"" + view + "\", the " + name +
          " \"" + text + "\" is not an angle in degrees from " +
          picture_number(low) + " to " + picture_number(high));
      return angle;
    }

    /// The range "<low>, <high>" of "Picture range" = @p text; none for
    /// "auto"; throws naming the entry otherwise.
    std::optional<std::pair<double, double>>
    colour_bar_range(const std::string &text)
    {
      if (text == "auto")
        return std::nullopt;
      const std::vector<std::string> ends =
        dealii::Utilities::split_string_list(text, ',');
      double low = NAN, high = NAN;
      if (ends.size() == 2)
        {
          char *rest_low = nullptr, *rest_high = nullptr;
          low  = std::strtod(ends[0].c_str(), &rest_low);
          high = std::strtod(ends[1].c_str(), &rest_high);
          if (*rest_low != '\0' || *rest_high != '\0')
            low = high = NAN;
        }
      if (!(std::isfinite(low) && std::isfinite(high) && low < high))
        throw std::invalid_argument(
          "entry \"Output/Picture range\": \"" + text +
          "\" should read \"auto\" or \"<low>, <high>\", two finite numbers "
          "with low < high");
      return std::make_pair(low, high);
    }
  } // namespace


  void
  PictureOptions::declare_entries(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Picture field",
                      "displacement",
                      Anything(),
                      "Colours the deformed rods of picture.png: "
                      "displacement, rod (index), group, a field of the VTU "
                      "files (curvature, axial_strain, ...; name[k]: "
                      "component k), or none (no picture). [-]");
    prm.declare_entry("Picture view",
                      "auto",
                      Anything(),
                      "The camera's azimuth (from x towards y) and "
                      "elevation (-90 to 90), as \"-60, 30\", or auto: "
                      "chosen from the shape. [deg]");
    prm.declare_entry("Picture interval",
                      "0",
                      Integer(0),
                      "Also draw picture-NNNNN.png at every n-th step (at "
                      "most 100: past it, every 2n-th...); 0: none. [-]");
    prm.declare_entry("Picture range",
                      "auto",
                      Anything(),
                      "The colour bar's range, \"<low>, <high>\", for every "
                      "picture; auto: the field's range over them all. [-]");
    prm.declare_entry("Picture groups",
                      "",
                      Anything(),
                      "For field group: the groups to colour (\"layer1, "
                      "layer2\"); a rod shows the first it is in. [-]");
  }


  void
  PictureOptions::parse_entries(dealii::ParameterHandler &prm)
  {
    field    = prm.get("Picture field");
    enabled  = field != "none";
    interval = prm.get_integer("Picture interval");
    range    = colour_bar_range(prm.get("Picture range"));
    groups.names =
      dealii::Utilities::split_string_list(prm.get("Picture groups"), ',');
    const std::string view = prm.get("Picture view");
    if (view == "auto")
      return;
    const std::vector<std::string> angles =
      dealii::Utilities::split_string_list(view, ',');
    if (angles.size() != 2)
      throw std::invalid_argument("entry \"Output/Picture view\": \"" + view +
                                  "\" should read \"auto\" or \"<azimuth>, "
                                  "<elevation>\" (degrees)");
    azimuth   = angle_of_view(view, angles[0], "azimuth", -360, 360);
    elevation = angle_of_view(view, angles[1], "elevation", -90, 90);
  }


  std::string
  network_picture_script(const RodNetwork     &network,
                         const PictureState   &state,
                         const PictureOptions &options,
                         const std::string    &png_path,
                         const std::string    &title,
                         ColourRange          *range)
  {
    const PictureField field = PictureFieldCatalogue(network,
                                                     state.positions,
                                                     state.fields,
                                                     options.groups)
                                 .select(options.field);
    ColourRange drawn_range = colour_range(field);
    if (range != nullptr)
      *range = drawn_range;
    if (options.range)
      std::tie(drawn_range.low, drawn_range.high) = *options.range;
    std::vector<Vector3> undeformed;
    for (unsigned int v = 0; v < network.n_vertices(); ++v)
      undeformed.push_back(network.vertex(v));
    const PictureCamera   camera = choose_camera(undeformed,
                                               state.positions,
                                               options.azimuth,
                                               options.elevation);
    std::vector<DrawnRod> rods   = drawn_rods(network, state, field, camera);
    const PictureFrame    frame(rods, options.size);
    const double          width = line_width(rods, frame);
    // Pieces shorter than 1.5 pixels are merged (a dense lattice).
    for (DrawnRod &rod : rods)
      {
        thin_out(rod.undeformed, nullptr, 1.5 / frame.scale);
        thin_out(rod.deformed, &rod.values, 1.5 / frame.scale);
      }
    const bool with_none = !field.categories.empty() && mark_no_category(rods);

    std::ostringstream script;
    script << "# rodnet picture: azimuth "
           << picture_number(camera.azimuth + 0.0) << ", elevation "
           << picture_number(camera.elevation + 0.0)
           << " degrees; screen coordinates (m) from the frame's centre\n"
           << layout_settings(frame, png_path, title)
           << colour_settings(drawn_range);
    if (field.categories.empty())
      script << "set cblabel " << gnuplot_quote(field.label) << "\n";
    else
      script << category_settings(frame, field.categories, field.label);
    write_picture_data(script, rods, frame.centre());
    script << "plot $undeformed with lines linecolor rgb '#c8c8c8' linewidth "
           << picture_number(0.6 * width, 3)
           << ", \\\n     $deformed using 1:2:"
           << (field.categories.empty() ?
                 "3 with lines linecolor palette" :
                 "(category_colour($3)) with lines linecolor rgb variable")
           << " linewidth " << picture_number(width, 3)
           << (field.categories.empty() ?
                 "" :
                 category_legend(field.categories, with_none, width))
           << "\n";
    return script.str();
  }


  void
  PictureOptions::resolve_groups(
    const std::vector<std::vector<std::string>> &rod_groups)
  {
    if (field == "group")
      groups = picture_groups(groups.names, rod_groups);
    else
      groups = {};
  }


  void
  ColourRange::include(const ColourRange &other)
  {
    low      = std::min(low, other.low);
    high     = std::max(high, other.high);
    integers = integers && other.integers;
  }


  std::string
  with_colour_range(const std::string &script, const ColourRange &range)
  {
    const std::size_t begin = script.find(colour_begin),
                      end   = script.find(colour_end);
    if (begin == std::string::npos || end == std::string::npos)
      throw std::invalid_argument(
        "with_colour_range: the script has no colour bar settings");
    return script.substr(0, begin) + colour_settings(range) +
           script.substr(end + colour_end.size());
  }
} // namespace rodnet
