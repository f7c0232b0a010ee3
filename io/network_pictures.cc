// NetworkPictures: the pictures of one run, the frames of its steps drawn
// at its end over one colour range.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <base/mpi_session.h>
#include <io/gnuplot.h>
#include <io/network_picture.h>
#include <io/picture_fields.h>
#include <io/run_limits.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace rodnet
{
  NetworkPictures::NetworkPictures(const RodNetwork     &network_,
                                   const PictureState   &sample,
                                   const PictureOptions &options_)
      : network(network_)
      , options(options_)
      , interval(options_.interval)
  {
    try
      {
        PictureFieldCatalogue(network,
                              sample.positions,
                              sample.fields,
                              options.groups)
          .select(options.field);
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument("entry \"Output/Picture field\": " +
                                    std::string(e.what()));
      }
  }


  std::optional<ColourRange>
  NetworkPictures::write_script(const PictureState &state,
                                const std::string  &png_path,
                                const std::string  &title)
  {
    if (failed || !writes_outputs())
      return std::nullopt;
    ColourRange range;
    std::string failure;
    try
      {
        std::ofstream script(png_path + ".gp");
        script << network_picture_script(network,
                                         state,
                                         options,
                                         png_path,
                                         title,
                                         &range);
        if (!script)
          failure = "cannot write \"" + png_path + ".gp\"";
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    if (failure.empty())
      return range;
    failed = true;
    std::cerr << "warning: no picture \"" << png_path << "\" (nor any later "
              << "of this run): " << failure << std::endl;
    return std::nullopt;
  }


  bool
  NetworkPictures::draw_script(const std::string &png_path,
                               const ColourRange &range)
  {
    if (failed)
      return false;
    std::string failure;
    try
      {
        std::ifstream      file(png_path + ".gp");
        std::ostringstream script;
        script << file.rdbuf();
        failure =
          draw_with_gnuplot(with_colour_range(script.str(), range), png_path);
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    if (failure.empty())
      return true;
    failed = true;
    std::cerr << "warning: no picture \"" << png_path << "\" (nor any later "
              << "of this run): " << failure << std::endl;
    return false;
  }


  void
  NetworkPictures::add_frame(const PictureState &state,
                             const unsigned int  step,
                             const std::string  &directory,
                             const std::string  &title)
  {
    if (interval == 0 || step % interval != 0)
      return;
    const std::string png_path = directory + "/picture-" +
                                 dealii::Utilities::int_to_string(step, 5) +
                                 ".png";
    const std::optional<ColourRange> range =
      write_script(state, png_path, title);
    if (!range)
      return;
    frames.push_back({step, png_path, *range});
    if (frames.size() <= run_limits::max_picture_frames)
      return;
    // Every other frame goes: the frames still span the run, twice as far
    // apart.
    interval *= 2;
    std::vector<Frame> kept;
    for (const Frame &frame : frames)
      if (frame.step % interval == 0)
        kept.push_back(frame);
      else
        std::remove((frame.png_path + ".gp").c_str());
    frames = kept;
  }


  bool
  NetworkPictures::finish(const PictureState &state,
                          const std::string  &directory,
                          const std::string  &title)
  {
    const std::string                png_path = directory + "/picture.png";
    const std::optional<ColourRange> own = write_script(state, png_path, title);
    if (!own)
      return false;
    // One range for all: the given one, or the field's over every picture.
    ColourRange range = *own;
    for (const Frame &frame : frames)
      range.include(frame.range);
    if (options.range)
      std::tie(range.low, range.high) = *options.range;
    if (interval != options.interval)
      std::cerr << "warning: picture-NNNNN.png drawn every " << interval
                << " steps, not every " << options.interval << ": "
                << frames.size() << " pictures, at most "
                << run_limits::max_picture_frames
                << " a run draws (raise \"Output/Picture interval\")"
                << std::endl;
    for (const Frame &frame : frames)
      draw_script(frame.png_path, range);
    return draw_script(png_path, range);
  }
} // namespace rodnet
