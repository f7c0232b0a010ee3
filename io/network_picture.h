#ifndef RODNET_IO_NETWORK_PICTURE_H
#define RODNET_IO_NETWORK_PICTURE_H

#include <deal.II/base/parameter_handler.h>

#include <core/model.h>
#include <core/output_fields.h>
#include <core/rod_network.h>

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
    /// Also picture-NNNNN.png at every interval-th step; 0: never.
    unsigned int interval = 0;
    /// Pixels of the longer side of the drawing (the kept script's
    /// "set terminal" line redraws it larger).
    unsigned int size = 1000;

    /// Declares the entries "Picture field", "Picture view" and "Picture
    /// interval" in the current subsection (Output).
    static void
    declare_entries(dealii::ParameterHandler &prm);

    /// Reads them from the current subsection; throws
    /// std::invalid_argument naming the entry ("Output/Picture view") for
    /// angles that are not two in range.
    void
    parse_entries(dealii::ParameterHandler &prm);
  };

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
    PictureState state;
    for (unsigned int v = 0; v < model.network().n_vertices(); ++v)
      state.positions.push_back(model.position(u, v));
    state.fields = model.output_fields(u);
    return state;
  }

  /**
   * The gnuplot script that draws @p state of @p network into @p png_path:
   * an orthographic 3D view (choose_camera(), or the angles of
   * @p options), both shapes scaled alike in every direction and filling
   * the frame, the undeformed rods thin and light grey behind, the
   * deformed ones coloured by the field @p options.field (viridis; an
   * integer field of a few values in bands) with a colour bar labelled
   * with the field's name and unit, @p title at the top left. Lines are
   * the thinner the more rods the picture holds, so that a dense lattice
   * stays readable; rods are drawn from the farthest to the nearest.
   * Throws std::invalid_argument for a field the state does not have.
   */
  std::string
  network_picture_script(const RodNetwork     &network,
                         const PictureState   &state,
                         const PictureOptions &options,
                         const std::string    &png_path,
                         const std::string    &title);

  /**
   * The pictures of one run (picture.png, picture-NNNNN.png). Drawing is a
   * convenience: where gnuplot is missing or fails, one warning line goes
   * to std::cerr and no further picture of the run is attempted; the run
   * goes on. In a parallel run only rank 0 draws.
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

    /// Draws @p state into @p png_path (and keeps its script as
    /// `<png_path>.gp`); returns whether it did.
    bool
    draw(const PictureState &state,
         const std::string  &png_path,
         const std::string  &title);

  private:
    const RodNetwork &network;
    PictureOptions    options;
    /// Whether a picture failed: the run draws no more.
    bool failed = false;
  };
} // namespace rodnet

#endif
