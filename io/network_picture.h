#ifndef RODNET_IO_NETWORK_PICTURE_H
#define RODNET_IO_NETWORK_PICTURE_H

#include <deal.II/base/parameter_handler.h>

#include <core/every_entry.h>
#include <core/model.h>
#include <core/output_fields.h>
#include <core/rod_network.h>
#include <io/picture_fields.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /// How a run draws its pictures (subsection Output, entries "Picture
  /// ...").
  struct PictureOptions
  {
    /// picture.png at the end of the run (where Output/Plot is true).
    bool enabled = true;
    /// The field that colours the deformed rods (PictureFieldCatalogue).
    std::string field = "displacement";
    /// The camera's angles in degrees; chosen from the shape if not given
    /// (choose_camera()).
    std::optional<double> azimuth, elevation;
    /// Also picture-NNNNN.png at every interval-th step; 0: never. Past
    /// run_limits::max_picture_frames the interval doubles
    /// (NetworkPictures::add_frame()).
    unsigned int interval = 0;
    /// The colour bar's range, low and high, for every picture of the run;
    /// none: the range of the field over the pictures of the run.
    std::optional<std::pair<double, double>> range;
    /// Pixels of the longer side of the drawing (the kept script's
    /// "set terminal" line redraws it larger).
    unsigned int size = 1000;
    /// The groups of field "group": as parse_entries() reads "Picture
    /// groups", names only; resolve_groups() gives each rod its group.
    PictureGroups groups;

    /// Declares the entries "Picture field", "Picture view", "Picture
    /// interval", "Picture range" and "Picture groups" in the current
    /// subsection (Output).
    static void
    declare_entries(dealii::ParameterHandler &prm);

    /// Reads them from the current subsection; throws
    /// std::invalid_argument naming the entry ("Output/Picture view") for
    /// angles that are not two in range, and a range that is not two
    /// increasing numbers.
    void
    parse_entries(dealii::ParameterHandler &prm);

    /// Where the field is "group", the groups read by parse_entries() for
    /// rods in the groups @p rod_groups (picture_groups(), which throws
    /// naming the entry "Output/Picture groups"); otherwise none.
    void
    resolve_groups(const std::vector<std::vector<std::string>> &rod_groups);
  };

  /// The range of a picture's colour bar: its ends, and whether the field
  /// has integer values only (drawn in bands where they are few).
  struct ColourRange
  {
    double low = INFINITY, high = -INFINITY;
    bool   integers = true;

    /// Widens this range to hold @p other as well.
    void
    include(const ColourRange &other);
  };

  /**
   * @p script, a network_picture_script(), with the colour bar's settings
   * (palette, range) made those of @p range: the frames of a run drawn
   * with one range (NetworkPictures).
   */
  std::string
  with_colour_range(const std::string &script, const ColourRange &range);

  /// What a picture draws of a state: the current position of every
  /// vertex and the model's fields (Model::output_fields()).
  struct PictureState
  {
    std::vector<Vector3> positions;
    OutputFields         fields;
  };

  /// The state @p u of @p model as a picture draws it; works alike for
  /// every model.
  template <class State>
  PictureState
  picture_state(const Model<State> &model, const State &u)
  {
    const EveryEntryOf<State> every_entry(u);
    PictureState              state;
    for (unsigned int v = 0; v < model.network().n_vertices(); ++v)
      state.positions.push_back(model.position(*every_entry, v));
    state.fields = model.output_fields(*every_entry);
    return state;
  }

  /**
   * The gnuplot script that draws @p state of @p network into @p png_path:
   * an orthographic 3D view (choose_camera(), or the angles of
   * @p options), both shapes scaled alike in every direction and filling
   * the frame, the undeformed rods thin and light grey behind, the
   * deformed ones coloured by the field @p options.field (viridis; an
   * integer field of a few values in bands) with a colour bar labelled
   * with the field's name and unit (picture_label()), over the range
   * @p options.range or else the field's own; a field of categories
   * ("group") in distinct colours, with a legend of their names instead
   * of the colour bar; @p title at the top left;
   * @p range, if given, receives the field's own range. Lines are
   * the thinner the more rods the picture holds, so that a dense lattice
   * stays readable; rods are drawn from the farthest to the nearest.
   * Throws std::invalid_argument for a field the state does not have.
   */
  std::string
  network_picture_script(const RodNetwork     &network,
                         const PictureState   &state,
                         const PictureOptions &options,
                         const std::string    &png_path,
                         const std::string    &title,
                         ColourRange          *range = nullptr);

  /**
   * The pictures of one run (picture.png, picture-NNNNN.png). Drawing is a
   * convenience: where gnuplot is missing or fails, one warning line goes
   * to std::cerr and no further picture of the run is attempted; the run
   * goes on. In a parallel run only rank 0 draws.
   *
   * The frames of the steps (add_frame()) are kept as their scripts
   * (picture-NNNNN.png.gp) and drawn at the end (finish()), with
   * picture.png, over one colour range: PictureOptions::range, or the
   * field's range over them all, so that a colour means one value in
   * every frame. At most run_limits::max_picture_frames are kept: past it
   * every other one is dropped and the interval doubles, so that the
   * frames always span the whole run.
   */
  class NetworkPictures
  {
  public:
    /**
     * Pictures of the states of @p model (which must outlive this
     * object). Throws std::invalid_argument naming the entry "Output/Picture
     * field" if the model has no such field, before any step.
     */
    template <class State>
    NetworkPictures(const Model<State> &model, const PictureOptions &options)
        : NetworkPictures(model.network(),
                          picture_state(model, model.create_vector()),
                          options)
    {
    }

    /// The same, checked against the fields of @p sample.
    NetworkPictures(const RodNetwork     &network,
                    const PictureState   &sample,
                    const PictureOptions &options);

    /// Keeps @p state of step @p step as the frame
    /// `<directory>/picture-NNNNN.png` if the step is on the interval
    /// (PictureOptions::interval, doubled as needed).
    void
    add_frame(const PictureState &state,
              unsigned int        step,
              const std::string  &directory,
              const std::string  &title);

    /**
     * Draws the frames kept and @p state, the last one, into
     * `<directory>/picture.png`; returns whether picture.png was drawn.
     * A line on std::cerr says where the interval was doubled.
     */
    bool
    finish(const PictureState &state,
           const std::string  &directory,
           const std::string  &title);

  private:
    /// A frame: its step, its image and its field's own range.
    struct Frame
    {
      unsigned int step;
      std::string  png_path;
      ColourRange  range;
    };

    /// Writes the script of @p state into `<png_path>.gp`; the field's own
    /// range, none where the script cannot be written (then drawing stops
    /// with a warning).
    std::optional<ColourRange>
    write_script(const PictureState &state,
                 const std::string  &png_path,
                 const std::string  &title);

    /// Runs gnuplot on `<png_path>.gp` with its colour bar over @p range;
    /// returns whether it drew the image (a warning and no more pictures
    /// if not).
    bool
    draw_script(const std::string &png_path, const ColourRange &range);

    const RodNetwork  &network;
    PictureOptions     options;
    std::vector<Frame> frames;
    /// The interval of the frames kept (PictureOptions::interval doubled
    /// as often as needed).
    unsigned int interval;
    /// Whether a picture failed: the run draws no more.
    bool failed = false;
  };
} // namespace rodnet

#endif
