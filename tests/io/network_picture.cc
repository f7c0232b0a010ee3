// picture.png, the deformed rods coloured by a field over the undeformed
// ones in grey: written by a run (Newton and dynamic relaxation alike),
// not blank, coloured across the whole colour bar by the field the scene
// chose (two fields of opposite trend swap the colours of the rod's ends),
// drawn without distortion (a ring stays round), at every n-th step on
// request, all over one colour range, at most 100 of them; without
// gnuplot the run succeeds and says so once; colour bars are labelled
// with readable names and units; rod groups in their colours with a legend
// naming them, rods of no listed group in grey. The PNGs are
// decoded (libpng) and their pixels checked.
#include <common/run_scene_text.h>
#include <common/scene_text.h>
#include <io/network_picture.h>
#include <io/picture_camera.h>
#include <io/picture_fields.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <png.h>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;
  using namespace rodnet;
  using namespace rodnet::testing;
  using Rgb = std::array<int, 3>;

  bool
  gnuplot_on_path()
  {
    const char        *path = std::getenv("PATH");
    std::istringstream dirs(path == nullptr ? "" : path);
    for (std::string dir; std::getline(dirs, dir, ':');)
      if (!dir.empty() && access((dir + "/gnuplot").c_str(), X_OK) == 0)
        return true;
    return false;
  }

  /// An RGB image decoded from a PNG file.
  struct Image
  {
    explicit Image(const fs::path &path)
    {
      png_image image{};
      image.version = PNG_IMAGE_VERSION;
      if (!png_image_begin_read_from_file(&image, path.c_str()))
        throw std::runtime_error("cannot read " + path.string());
      image.format = PNG_FORMAT_RGB;
      width        = image.width;
      height       = image.height;
      bytes.resize(PNG_IMAGE_SIZE(image));
      if (!png_image_finish_read(&image, nullptr, bytes.data(), 0, nullptr))
        throw std::runtime_error("cannot decode " + path.string());
    }

    Rgb
    at(const unsigned int x, const unsigned int y) const
    {
      const std::size_t k = 3 * (std::size_t(y) * width + x);
      return {{bytes[k], bytes[k + 1], bytes[k + 2]}};
    }

    unsigned int               width = 0, height = 0;
    std::vector<unsigned char> bytes;
  };

  /// How far a pixel is from grey: a colour of the palette, not the
  /// background, the grey undeformed rods or black text.
  int
  saturation(const Rgb &c)
  {
    return *std::max_element(c.begin(), c.end()) -
           *std::min_element(c.begin(), c.end());
  }

  double
  distance(const Rgb &a, const Rgb &b)
  {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }

  /// What a picture shows: where its colour bar is, the bar's colours at
  /// its low and high ends, and the coloured pixels left of it (the
  /// deformed rods) with their columns.
  struct PictureContent
  {
    unsigned int bar_column = 0;
    Rgb          low{}, high{};
    /// (column, row, colour) of every coloured pixel of the drawing.
    std::vector<std::pair<std::array<unsigned int, 2>, Rgb>> drawn;
    /// Pixels of the drawing that are not background (white).
    std::size_t not_background = 0, grey = 0;
  };

  PictureContent
  content_of(const Image &image)
  {
    PictureContent content;
    // The colour bar: the rightmost column with a long run of colour.
    for (unsigned int x = image.width; x-- > 0 && content.bar_column == 0;)
      {
        std::vector<unsigned int> rows;
        for (unsigned int y = 0; y < image.height; ++y)
          if (saturation(image.at(x, y)) > 60)
            rows.push_back(y);
        if (rows.size() > image.height / 4)
          {
            // Inside the bar, clear of its border and tic marks.
            content.bar_column = x;
            content.high       = image.at(x - 8, rows.front() + 3);
            content.low        = image.at(x - 8, rows.back() - 3);
          }
      }
    for (unsigned int x = 0; x + 40 < content.bar_column; ++x)
      for (unsigned int y = 0; y < image.height; ++y)
        {
          const Rgb c = image.at(x, y);
          content.not_background += c != Rgb{{255, 255, 255}};
          content.grey += saturation(c) < 8 && c[0] > 150 && c[0] < 235;
          if (saturation(c) > 60)
            content.drawn.push_back({{{x, y}}, c});
        }
    return content;
  }

  /// The most saturated colour among the drawn pixels within 4 columns of
  /// the leftmost (@p leftmost) or rightmost one: the line's core, not
  /// its antialiased edge.
  Rgb
  end_colour(const PictureContent &content, const bool leftmost)
  {
    unsigned int edge = leftmost ? ~0u : 0;
    for (const auto &[xy, c] : content.drawn)
      edge = leftmost ? std::min(edge, xy[0]) : std::max(edge, xy[0]);
    Rgb best{};
    for (const auto &[xy, c] : content.drawn)
      if ((leftmost ? xy[0] - edge : edge - xy[0]) <= 4 &&
          saturation(c) > saturation(best))
        best = c;
    return best;
  }

  /// A cantilever along x of length 1 with 20 segments, clamped at x = 0
  /// and bent in the xy-plane by a tip force along y (PL^2/EI = 2, a tip
  /// rotation near 40 degrees), solved by @p method in 2 steps; its
  /// picture coloured by @p field.
  std::string
  bent_cantilever(const std::string &field,
                  const std::string &method = "newton",
                  const std::string &extra  = "")
  {
    return "subsection Geometry\n  set Segments = 20\n"
           "  set Director d1 = 0, 0.6, 0.8\nend\n" +
           direct_material() +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n  set Steps = 2\n"
           "  set Point forces = end: 0, 2, 0\nend\n"
           "subsection Solver\n  set Method = " +
           method +
           "\nend\n"
           "subsection Output\n  set Write VTU = false\n"
           "  set Picture field = " +
           field + "\n" + extra + "end\n";
  }

  /// Runs @p scene into network_picture_tests/@p name; its picture.png.
  Image
  picture_of_run(const std::string &scene, const std::string &name)
  {
    const std::string dir = "network_picture_tests/" + name;
    fs::remove_all(dir);
    const RunSummary run = run_scene_text(scene, dir);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    EXPECT_NE(std::find(run.outputs.begin(), run.outputs.end(), "picture.png"),
              run.outputs.end());
    return Image(dir + "/picture.png");
  }

  TEST(NetworkPicture, RunDrawsTheRodColouredAcrossTheColourBar)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // u_y grows from 0 at the clamp to its largest at the tip: the rod's
    // colours run from the bar's low end to its high end.
    const Image image =
      picture_of_run(bent_cantilever("displacement[2]"), "displacement_y");
    const PictureContent content = content_of(image);
    ASSERT_GT(content.bar_column, image.width / 2);
    // Dark violet below, yellow above (viridis).
    EXPECT_GT(distance(content.low, content.high), 200);
    // The rod, 3 pixels wide over some 1000, is drawn in colour; the
    // undeformed one in grey.
    const double area = double(content.bar_column) * image.height;
    EXPECT_GT(content.drawn.size(), 1000u);
    EXPECT_GT(content.not_background, 0.005 * area);
    EXPECT_GT(content.grey, 500u);
    // Colours near both ends of the bar are drawn.
    for (const Rgb &end : {content.low, content.high})
      EXPECT_TRUE(std::any_of(content.drawn.begin(),
                              content.drawn.end(),
                              [&](const auto &p) {
                                return distance(p.second, end) < 30;
                              }))
        << end[0] << " " << end[1] << " " << end[2];
    EXPECT_LT(distance(end_colour(content, true), content.low), 40);
    EXPECT_LT(distance(end_colour(content, false), content.high), 40);
  }

  TEST(NetworkPicture, TheChosenFieldColoursTheRod)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // u_x falls from 0 at the clamp to its least at the tip, u_y rises:
    // the ends of the rod swap colours between the two pictures.
    const PictureContent x = content_of(
      picture_of_run(bent_cantilever("displacement[1]"), "displacement_x"));
    const PictureContent y = content_of(
      picture_of_run(bent_cantilever("displacement[2]"), "displacement_y2"));
    EXPECT_LT(distance(end_colour(x, true), x.high), 40);
    EXPECT_LT(distance(end_colour(x, false), x.low), 40);
    EXPECT_LT(distance(end_colour(y, true), y.low), 40);
    EXPECT_LT(distance(end_colour(y, false), y.high), 40);
  }

  TEST(NetworkPicture, DynamicRelaxationRunIsDrawnToo)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const PictureContent content = content_of(
      picture_of_run(bent_cantilever("displacement[2]", "dynamic relaxation"),
                     "dynamic_relaxation"));
    EXPECT_GT(content.drawn.size(), 1000u);
    EXPECT_LT(distance(end_colour(content, true), content.low), 40);
    EXPECT_LT(distance(end_colour(content, false), content.high), 40);
  }

  TEST(NetworkPicture, RodIndexInOneBandPerRod)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // The frame's two rods (indices 0 and 1), its tip pushed out of its
    // plane: one in the bar's low colour, one in its high colour, and no
    // colour between (a band per rod, no gradient).
    const std::string scene =
      "subsection Geometry\n  set Generator = frame\n  set Segments = 8\n"
      "end\n" +
      direct_material("100") +
      "subsection Supports\n  set Prescribed displacements = @tip: z=0.3\n"
      "end\nsubsection Output\n  set Write VTU = false\n"
      "  set Picture field = rod\nend\n";
    const PictureContent content = content_of(picture_of_run(scene, "rods"));
    const Rgb            middle{{0x21, 0x91, 0x8c}};
    std::size_t          low = 0, high = 0, between = 0;
    for (const auto &[xy, c] : content.drawn)
      {
        low += distance(c, content.low) < 30;
        high += distance(c, content.high) < 30;
        between += distance(c, middle) < 30;
      }
    EXPECT_GT(low, 500u);
    EXPECT_GT(high, 500u);
    EXPECT_EQ(between, 0u);
    EXPECT_GT(distance(content.low, content.high), 200);
  }

  /// A picture's legend: (colour, name) of every entry.
  using Legend = std::vector<std::pair<Rgb, std::string>>;

  /// The legend entries of the script @p path: (colour, name) of every
  /// "keyentry ... rgb '#rrggbb' ... title 'name'" line.
  Legend
  legend_of(const std::string &path)
  {
    Legend        legend;
    std::ifstream script(path);
    for (std::string line; std::getline(script, line);)
      {
        const std::size_t key   = line.find("keyentry"),
                          rgb   = line.find("rgb '#"),
                          title = line.find("title '");
        if (key == std::string::npos || rgb == std::string::npos ||
            title == std::string::npos)
          continue;
        const long colour = std::stol(line.substr(rgb + 6, 6), nullptr, 16);
        const std::string name = line.substr(title + 7);
        legend.push_back(
          {{{int(colour >> 16), int(colour >> 8 & 0xff), int(colour & 0xff)}},
           name.substr(0, name.find('\''))});
      }
    return legend;
  }

  /// The pixels (column, row) of the drawing of @p image, left of the
  /// legend's margin (150 pixels), within @p tolerance of @p colour.
  std::vector<std::array<unsigned int, 2>>
  pixels_near(const Image &image, const Rgb &colour, const double tolerance)
  {
    std::vector<std::array<unsigned int, 2>> pixels;
    for (unsigned int x = 0; x + 150 < image.width; ++x)
      for (unsigned int y = 0; y < image.height; ++y)
        if (distance(image.at(x, y), colour) < tolerance)
          pixels.push_back({{x, y}});
    return pixels;
  }

  /// A 2 x 2 square lattice of side 1 in the xy-plane, clamped at n_0_0
  /// and pushed out of its plane a little at n_2_2, seen from above, its
  /// picture coloured by "group" with Picture groups = @p groups.
  std::string
  lattice_by_groups(const std::string &groups)
  {
    return "subsection Geometry\n  set Generator = square lattice\n"
           "  set Cells = 2, 2\n  set Beam length = 1\n  set Segments = 4\n"
           "end\n" +
           direct_material("100") +
           "subsection Supports\n  set Clamped ends = @n_0_0\nend\n"
           "subsection Loads\n  set Point forces = @n_2_2: 0, 0, 1e-3\nend\n"
           "subsection Output\n  set Write VTU = false\n"
           "  set Picture field = group\n  set Picture view = -90, 90\n"
           "  set Picture groups = " +
           groups + "\nend\n";
  }

  /// The names of @p legend's entries, in order.
  std::vector<std::string>
  names_of(const Legend &legend)
  {
    std::vector<std::string> names;
    for (const auto &entry : legend)
      names.push_back(entry.second);
    return names;
  }

  /// Runs lattice_by_groups(@p groups) into network_picture_tests/@p name:
  /// its picture and the legend of its script.
  std::pair<Image, Legend>
  lattice_picture(const std::string &groups, const std::string &name)
  {
    Image image = picture_of_run(lattice_by_groups(groups), name);
    return {std::move(image),
            legend_of("network_picture_tests/" + name + "/picture.png.gp")};
  }

  TEST(NetworkPicture, GroupsInTheirColoursWithALegend)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // Seen from above, the x-beams are the horizontal lines of the
    // picture, the y-beams the vertical ones: each group in the colour its
    // legend entry gives it, two colours far apart, and no colour bar.
    const auto [image, legend] = lattice_picture("x-beams, y-beams", "groups");
    ASSERT_EQ(names_of(legend),
              (std::vector<std::string>{"x-beams", "y-beams"}));
    EXPECT_GT(distance(legend[0].first, legend[1].first), 150);
    // The rows and columns each group's pixels cover.
    for (unsigned int g = 0; g < 2; ++g)
      {
        const auto             pixels = pixels_near(image, legend[g].first, 30);
        std::set<unsigned int> rows, columns;
        for (const auto &[x, y] : pixels)
          rows.insert(y), columns.insert(x);
        EXPECT_GT(pixels.size(), 1000u) << legend[g].second;
        // Three lines, some 3 pixels wide, over most of the drawing:
        // x-beams (g = 0) horizontal, y-beams vertical.
        EXPECT_LT((g == 0 ? rows : columns).size(), 30u) << legend[g].second;
        EXPECT_GT((g == 0 ? columns : rows).size(), 300u) << legend[g].second;
      }
  }

  TEST(NetworkPicture, RodsOfNoListedGroupInGrey)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // Only the boundary listed: the interior beams (the middle row and
    // column) are grey and the legend says so.
    const auto [image, legend] = lattice_picture("boundary", "groups_other");
    ASSERT_EQ(names_of(legend),
              (std::vector<std::string>{"boundary", "(other)"}));
    EXPECT_LT(saturation(legend[1].first), 8);
    // Eight boundary beams, four interior ones.
    EXPECT_GT(pixels_near(image, legend[0].first, 30).size(), 2000u);
    EXPECT_GT(pixels_near(image, legend[1].first, 20).size(), 1000u);
  }

  TEST(PictureGroups, FirstListedGroupOfEachRod)
  {
    // The list's order settles a rod in two listed groups; a rod in none
    // shows none (-1); "all" holds every rod.
    const std::vector<std::vector<std::string>> rods{{"x-beams", "boundary"},
                                                     {"y-beams", "interior"},
                                                     {"y-beams", "boundary"},
                                                     {"struts"}};
    EXPECT_EQ(picture_groups({"y-beams", "boundary"}, rods).rod_group,
              (std::vector<int>{1, 0, 0, -1}));
    EXPECT_EQ(picture_groups({"boundary", "y-beams"}, rods).rod_group,
              (std::vector<int>{0, 1, 0, -1}));
    EXPECT_EQ(picture_groups({"interior", "all"}, rods).rod_group,
              (std::vector<int>{1, 0, 1, 1}));
    for (const auto &[listed, fragment] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{}, "colours the rods by the groups this entry lists"},
           {{"x-beam"},
            "no rod is in group \"x-beam\"; the groups of this geometry are "
            "\"x-beams\""},
           {{"boundary", "boundary"}, "\"boundary\" is listed twice"},
           {{"1", "2", "3", "4", "5", "6", "7", "8"},
            "8 groups, more than the 7 colours"}})
      try
        {
          picture_groups(listed, rods);
          ADD_FAILURE() << fragment << ": no error";
        }
      catch (const std::invalid_argument &e)
        {
          const std::string message = e.what();
          EXPECT_EQ(message.find("entry \"Output/Picture groups\": "), 0u)
            << message;
          EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
  }

  TEST(NetworkPicture, RodEndsTakeTheirNeighboursCurvature)
  {
    // A cantilever bent by an end moment M = EI into an arc of curvature
    // 1/m: every piece of the drawn rod carries kappa = 1, the half
    // segments at its ends too (its end vertices have no hinge: the
    // model's output gives them 0, which would draw two spots of zero),
    // while a field with values at the ends (displacement) keeps them (the
    // tests above: the clamp in the bar's low colour). The script's
    // $deformed block: x, y, value.
    const std::string dir = "network_picture_tests/end_moment";
    fs::remove_all(dir);
    const RunSummary run =
      run_scene_text("subsection Geometry\n  set Segments = 20\nend\n" +
                       direct_material() +
                       "subsection Supports\n  set Clamped ends = start\nend\n"
                       "subsection Loads\n  set Steps = 2\n"
                       "  set Moments = end: 0,0,1 1\nend\n"
                       "subsection Output\n  set Write VTU = false\n"
                       "  set Picture field = curvature\nend\n",
                     dir);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    std::ifstream script(dir + "/picture.png.gp");
    std::string   line;
    while (std::getline(script, line) && line != "$deformed << EOD")
      ;
    // The discrete curvature of the arc, 2 tan(h kappa / 2) / h, is
    // kappa (1 + (h kappa)^2 / 12): 2e-4 above it at h = 0.05.
    std::vector<double> values;
    while (std::getline(script, line) && line != "EOD")
      if (!line.empty())
        {
          double x, y, kappa;
          std::istringstream(line) >> x >> y >> kappa;
          EXPECT_NEAR(kappa, 1, 1e-3) << line;
          values.push_back(kappa);
        }
    // 21 vertices and 20 midpoints, all of one value.
    ASSERT_EQ(values.size(), 41u);
    for (const double kappa : values)
      EXPECT_NEAR(kappa, values[20], 1e-9 * values[20]);
  }

  TEST(NetworkPicture, RingStaysRound)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // A ring of radius 1 in the xy-plane, hardly loaded: seen from above,
    // its drawing is as wide as high (equal scales), to 1 % of its width
    // plus the line's width; coloured by the rod's index (one rod: one
    // colour band).
    const std::string scene =
      "subsection Geometry\n  set Generator = ring\n  set Radius = 1\n"
      "  set Plane axis 1 = 1, 0, 0\n  set Plane axis 2 = 0, 1, 0\n"
      "  set Segments = 80\n  set Director d1 = 0, 0, 1\nend\n" +
      direct_material() +
      "subsection Supports\n  set Pinned vertices = 60\n"
      "  set Fixed components = 20: x z; 0: z\nend\n"
      "subsection Loads\n  set Steps = 1\n"
      "  set Point forces = 20: 0, -1e-6, 0\nend\n"
      "subsection Output\n  set Write VTU = false\n"
      "  set Picture field = curvature\nend\n";
    const PictureContent content = content_of(picture_of_run(scene, "ring"));
    std::array<unsigned int, 2> low{{~0u, ~0u}}, high{{0, 0}};
    for (const auto &[xy, c] : content.drawn)
      for (unsigned int k = 0; k < 2; ++k)
        {
          low[k]  = std::min(low[k], xy[k]);
          high[k] = std::max(high[k], xy[k]);
        }
    const double width = high[0] - low[0], height = high[1] - low[1];
    EXPECT_GT(width, 500);
    EXPECT_NEAR(height / width, 1.0, 0.01);
  }

  TEST(NetworkPicture, PicturesAtEveryNthStep)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const std::string dir = "network_picture_tests/steps";
    fs::remove_all(dir);
    const RunSummary run = run_scene_text(
      bent_cantilever("rod", "newton", "  set Picture interval = 2\n"),
      dir);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    for (const char *file :
         {"picture-00000.png", "picture-00002.png", "picture.png"})
      EXPECT_TRUE(fs::exists(dir + "/" + file)) << file;
    EXPECT_FALSE(fs::exists(dir + "/picture-00001.png"));
  }

  /// The line "set cbrange [...]" of the script @p path.
  std::string
  colour_bar_range(const std::string &path)
  {
    std::ifstream script(path);
    std::string   line;
    while (std::getline(script, line))
      if (line.rfind("set cbrange", 0) == 0)
        return line;
    return "";
  }

  /// The largest value of the $deformed block of the script @p path.
  double
  largest_drawn_value(const std::string &path)
  {
    std::ifstream script(path);
    std::string   line;
    while (std::getline(script, line) && line != "$deformed << EOD")
      ;
    double largest = -INFINITY;
    while (std::getline(script, line) && line != "EOD")
      if (!line.empty())
        {
          double x, y, value;
          std::istringstream(line) >> x >> y >> value;
          largest = std::max(largest, value);
        }
    return largest;
  }

  TEST(NetworkPicture, FramesShareOneColourRange)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // |u| of the bent cantilever at steps 0 (zero everywhere), 1 and 2: one
    // bar from 0 to the largest |u| of any frame (the tip's at step 2) in
    // every picture; step 0 drawn all in the bar's low colour (over its
    // own range, a constant, it would sit in the bar's middle).
    const std::string dir = "network_picture_tests/frames";
    fs::remove_all(dir);
    const RunSummary run = run_scene_text(
      bent_cantilever("displacement", "newton", "  set Picture interval = 1\n"),
      dir);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double tip = largest_drawn_value(dir + "/picture.png.gp");
    EXPECT_GT(tip, 0.3);
    const std::string range = colour_bar_range(dir + "/picture.png.gp");
    double            low = NAN, high = NAN;
    ASSERT_EQ(std::sscanf(range.c_str(), "set cbrange [%lf:%lf]", &low, &high),
              2)
      << range;
    EXPECT_EQ(low, 0.);
    EXPECT_NEAR(high, tip, 1e-5 * tip);
    for (const std::string file :
         {"picture-00000.png", "picture-00001.png", "picture-00002.png"})
      EXPECT_EQ(colour_bar_range(dir + "/" + file + ".gp"), range) << file;
    const PictureContent first = content_of(Image(dir + "/picture-00000.png"));
    ASSERT_GT(first.drawn.size(), 500u);
    for (const auto &[xy, c] : first.drawn)
      EXPECT_LT(distance(c, first.low), 60) << xy[0] << ", " << xy[1];
  }

  TEST(NetworkPicture, GivenRangeForEveryPicture)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const std::string dir = "network_picture_tests/given_range";
    fs::remove_all(dir);
    const RunSummary run =
      run_scene_text(bent_cantilever("displacement",
                                     "newton",
                                     "  set Picture interval = 1\n"
                                     "  set Picture range = 0, 5\n"),
                     dir);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    for (const std::string file :
         {"picture-00000.png", "picture-00002.png", "picture.png"})
      EXPECT_EQ(colour_bar_range(dir + "/" + file + ".gp"), "set cbrange [0:5]")
        << file;
  }

  TEST(NetworkPicture, FramesAreCappedAndSpanTheRun)
  {
    if (!gnuplot_on_path())
      GTEST_SKIP() << "gnuplot is not on PATH";
    // 250 steps, a picture asked for at each: past 100 frames every other
    // one goes (twice, at steps 100 and 200), leaving every 4th step from
    // 0 to 248, 63 pictures, and one warning that says so.
    const std::string dir = "network_picture_tests/capped";
    fs::remove_all(dir);
    std::string scene =
      bent_cantilever("rod", "newton", "  set Picture interval = 1\n");
    scene.replace(scene.find("set Steps = 2"), 13, "set Steps = 250");
    ::testing::internal::CaptureStderr();
    const RunSummary  run      = run_scene_text(scene, dir);
    const std::string messages = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    std::vector<unsigned int> steps;
    for (const auto &entry : fs::directory_iterator(dir))
      {
        const std::string name = entry.path().filename().string();
        if (name.rfind("picture-", 0) == 0 && name.size() == 17 &&
            name.substr(13) == ".png")
          steps.push_back(std::stoul(name.substr(8, 5)));
      }
    std::sort(steps.begin(), steps.end());
    ASSERT_EQ(steps.size(), 63u);
    for (std::size_t k = 0; k < steps.size(); ++k)
      EXPECT_EQ(steps[k], 4 * k);
    EXPECT_FALSE(fs::exists(dir + "/picture-00002.png.gp"));
    EXPECT_NE(messages.find("warning: picture-NNNNN.png drawn every 4 steps, "
                            "not every 1: 63 pictures, at most 100"),
              std::string::npos)
      << messages;
  }

  TEST(NetworkPicture, ActivationFieldAtTheLastLoadFactor)
  {
    // A natural curvature 2 on [0.3, 0.6] of the cantilever (20 segments
    // of 0.05: the region's ends on vertices), ramped: picture.png, at
    // load factor 1, draws 2 on the region and 0 elsewhere.
    const std::string dir = "network_picture_tests/activation";
    fs::remove_all(dir);
    const RunSummary run = run_scene_text(
      bent_cantilever("activation_curvature_1") +
        "subsection Group all\n  set Natural curvature = 2, 0 on 0.3 to "
        "0.6\nend\n",
      dir);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    EXPECT_NEAR(largest_drawn_value(dir + "/picture.png.gp"), 2, 1e-12);
    std::ifstream script(dir + "/picture.png.gp");
    std::string   line;
    while (std::getline(script, line) && line != "$deformed << EOD")
      ;
    std::size_t twos = 0, zeros = 0;
    while (std::getline(script, line) && line != "EOD")
      if (!line.empty())
        {
          double x, y, value;
          std::istringstream(line) >> x >> y >> value;
          twos += std::abs(value - 2) < 1e-12;
          zeros += std::abs(value) < 1e-12;
        }
    EXPECT_GT(twos, 0u);
    EXPECT_GT(zeros, 0u);
  }

  TEST(PictureLabels, ReadableNamesWithUnits)
  {
    for (const auto &[name, unit, components, label] : std::vector<
           std::tuple<std::string, std::string, unsigned int, std::string>>{
           {"displacement", "m", 3, "|u| (m)"},
           {"displacement[3]", "m", 3, "u_z (m)"},
           {"curvature[1]", "1/m", 3, "kappa_1 (1/m)"},
           {"twist_rate", "rad/m", 1, "twist rate (rad/m)"},
           {"axial_strain", "-", 1, "axial strain"},
           {"d1[2]", "-", 3, "d1_y"},
           {"rod", "-", 1, "rod"},
           {"activation_curvature_1",
            "1/m",
            1,
            "activation curvature 1 (1/m)"}})
      EXPECT_EQ(picture_label(name, unit, components), label);
    // Every field a run offers: no brackets, the unit in parentheses.
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm,
                    bent_cantilever("rod") +
                      "subsection Group all\n  set Natural twist = 1\nend\n",
                    "scene",
                    false);
    const Scene                     scene(prm);
    const std::unique_ptr<RodModel> model = scene.build_model();
    const PictureState state = picture_state(*model, model->create_vector());
    const PictureFieldCatalogue catalogue(model->network(),
                                          state.positions,
                                          state.fields);
    for (const std::string &name : catalogue.names())
      {
        const PictureField field = catalogue.select(name);
        EXPECT_EQ(field.label.find_first_of("[]"), std::string::npos) << name;
        if (field.unit != "-")
          EXPECT_EQ(field.label.substr(field.label.size() - field.unit.size() -
                                       2),
                    "(" + field.unit + ")")
            << name;
      }
    EXPECT_NO_THROW(catalogue.select("activation_twist"));
  }

  TEST(NetworkPicture, NoPictureWithoutPlotsOrWithFieldNone)
  {
    for (const std::string entry :
         {"  set Plot = false\n", "  set Picture field = none\n"})
      {
        const std::string dir = "network_picture_tests/none";
        fs::remove_all(dir);
        const RunSummary run =
          run_scene_text(bent_cantilever("rod", "newton", entry), dir);
        EXPECT_TRUE(run.failure.empty()) << run.failure;
        EXPECT_FALSE(fs::exists(dir + "/picture.png")) << entry;
      }
  }

  TEST(NetworkPicture, WithoutGnuplotTheRunSucceedsAndSaysSoOnce)
  {
    const std::string dir = "network_picture_tests/no_gnuplot";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    setenv("PATH", fs::absolute(dir).c_str(), 1);
    ::testing::internal::CaptureStderr();
    const RunSummary run = run_scene_text(
      bent_cantilever("rod", "newton", "  set Picture interval = 1\n"),
      dir);
    const std::string messages = ::testing::internal::GetCapturedStderr();
    setenv("PATH", path.c_str(), 1);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    EXPECT_EQ(run.rows.size(), 3u);
    EXPECT_NE(messages.find("warning: no picture"), std::string::npos)
      << messages;
    EXPECT_NE(messages.find("gnuplot"), std::string::npos) << messages;
    EXPECT_EQ(std::count(messages.begin(), messages.end(), '\n'), 1)
      << messages;
    EXPECT_FALSE(fs::exists(dir + "/picture.png"));
  }

  TEST(NetworkPicture, UnknownFieldIsRefusedBeforeAnyStep)
  {
    const std::string dir = "network_picture_tests/unknown_field";
    fs::remove_all(dir);
    try
      {
        run_scene_text(bent_cantilever("curvatur"), dir);
        FAIL() << "no error";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("entry \"Output/Picture field\": no field "
                               "\"curvatur\""),
                  std::string::npos)
          << message;
        EXPECT_NE(message.find("nearest: \"curvature\""), std::string::npos)
          << message;
      }
    // No step was recorded: probes.csv holds its header at most.
    std::ifstream csv(dir + "/probes.csv");
    std::string   line;
    unsigned int  lines = 0;
    while (std::getline(csv, line))
      ++lines;
    EXPECT_LE(lines, 1u);
  }

  TEST(NetworkPicture, ViewsThatAreNotTwoAnglesInRangeAreRefused)
  {
    for (const auto &[view, fragment] :
         std::vector<std::pair<std::string, std::string>>{
           {"-60, 95",
            "the elevation \"95\" is not an angle in degrees "
            "from -90 to 90"},
           {"-60, high", "the elevation \"high\" is not an angle"},
           {"400, 30", "the azimuth \"400\" is not an angle"},
           {"30", "should read \"auto\" or \"<azimuth>, <elevation>\""}})
      try
        {
          run_scene_text(bent_cantilever("rod",
                                         "newton",
                                         "  set Picture view = " + view + "\n"),
                         "network_picture_tests/views");
          ADD_FAILURE() << view << ": no error";
        }
      catch (const std::invalid_argument &e)
        {
          const std::string message = e.what();
          EXPECT_EQ(message.find("entry \"Output/Picture view\": "), 0u)
            << message;
          EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
  }

  TEST(PictureCamera, AutomaticViews)
  {
    // A straight rod along x that bends in the xy-plane: seen from above,
    // x to the right, y up.
    const std::vector<Vector3> rod = {{0, 0, 0}, {1, 0, 0}};
    const PictureCamera        top = choose_camera(rod,
                                            {{0, 0, 0}, {0.8, 0.5, 0}},
                                            std::nullopt,
                                            std::nullopt);
    EXPECT_NEAR(top.elevation, 90, 1e-9);
    EXPECT_NEAR(top.project({1, 0, 0})[0], 1, 1e-12);
    EXPECT_NEAR(top.project({0, 1, 0})[1], 1, 1e-12);
    // Bending in the xz-plane: from -y, z up.
    const PictureCamera front = choose_camera(rod,
                                              {{0, 0, 0}, {0.8, 0, 0.5}},
                                              std::nullopt,
                                              std::nullopt);
    EXPECT_NEAR(front.elevation, 0, 1e-9);
    EXPECT_NEAR(front.azimuth, -90, 1e-9);
    EXPECT_NEAR(front.project({0, 0, 1})[1], 1, 1e-12);
    // A straight rod that bends out of every plane: the usual oblique
    // view.
    const PictureCamera general =
      choose_camera({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}},
                    {{0, 0, 0}, {0.5, 0.1, 0}, {0.8, 0.5, 0.3}},
                    std::nullopt,
                    std::nullopt);
    EXPECT_NEAR(general.azimuth, -60, 1e-12);
    EXPECT_NEAR(general.elevation, 30, 1e-12);
    // A flat square buckled out of its plane: 35 degrees above it.
    const std::vector<Vector3> square = {{0, 0, 0},
                                         {1, 0, 0},
                                         {1, 1, 0},
                                         {0, 1, 0}};
    const PictureCamera        oblique =
      choose_camera(square,
                    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.3}, {0, 1, 0}},
                    std::nullopt,
                    std::nullopt);
    EXPECT_NEAR(oblique.elevation, 35, 1e-9);
    EXPECT_NEAR(oblique.azimuth, -60, 1e-9);
    // Given angles win; the screen axes stay orthonormal.
    const PictureCamera given =
      choose_camera(square, square, -20.0, std::nullopt);
    EXPECT_NEAR(given.azimuth, -20, 1e-12);
    EXPECT_NEAR(given.elevation, 90, 1e-9);
    for (const PictureCamera &c : {top, front, oblique, given})
      {
        EXPECT_NEAR(c.right.dot(c.up), 0, 1e-12);
        EXPECT_NEAR(c.up.dot(c.toward_viewer), 0, 1e-12);
        EXPECT_NEAR(c.up.norm(), 1, 1e-12);
      }
  }
} // namespace
