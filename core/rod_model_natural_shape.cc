// RodModel: a natural shape ramped with the load factor, activation
// fields and their time, and what the potential follows of the two.
#include <core/rod_model.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rodnet
{
  void
  RodModel::ramp_natural_shape(const NaturalShapeParts         &parts,
                               const std::vector<unsigned int> &rods)
  {
    given_materials.resize(materials.size());
    for (const unsigned int rod : rods)
      {
        if (rod >= materials.size())
          throw std::invalid_argument(
            "ramp_natural_shape: there is no rod " + std::to_string(rod) +
            " (the network has " + std::to_string(materials.size()) + ")");
        if (!given_materials[rod])
          given_materials[rod] = materials[rod];
        try
          {
            // Also checks, now, that the material has a natural shape.
            materials[rod] =
              given_materials[rod]->with_natural_shape_scaled(parts, 0.0);
          }
        catch (const std::invalid_argument &e)
          {
            throw std::invalid_argument("rod " + std::to_string(rod) + ": " +
                                        e.what());
          }
      }
    ramped_parts = parts;
    ramped_at    = 0.0;
  }


  void
  RodModel::add_activation(const unsigned int     rod,
                           const ActivationField &field,
                           const ActivationDrive &drive)
  {
    require_not_finalized("RodModel::add_activation on rod " +
                          std::to_string(rod));
    if (rod >= materials.size())
      throw std::invalid_argument("add_activation: there is no rod " +
                                  std::to_string(rod) + " (the network has " +
                                  std::to_string(materials.size()) + ")");
    configuration_->add_activation(rod, field, drive);
  }


  void
  RodModel::set_time(const double time)
  {
    support_time = time;
    configuration_->set_activation_time(time);
  }


  std::vector<double>
  RodModel::activation_time_factors() const
  {
    return configuration_->activation_time_factors();
  }


  bool
  RodModel::potential_follows_load_factor() const
  {
    // Applied moments and the weight of bodies off their vertex are
    // families that say whether they follow it.
    const bool ramped_loads = f_ext.linfty_norm() != 0;
    const bool ramped_shape =
      std::any_of(given_materials.begin(),
                  given_materials.end(),
                  [](const auto &material) { return material != nullptr; });
    const bool ramped_family =
      !loads_fixed &&
      std::any_of(families.begin(), families.end(), [](const auto &family) {
        return family->follows_load_factor();
      });
    return (ramped_loads && !loads_fixed) || ramped_shape || ramped_family ||
           configuration_->has_activation_driven_by(
             ActivationDrive::Kind::load_factor);
  }


  bool
  RodModel::potential_follows_time() const
  {
    return configuration_->has_activation_driven_by(
      ActivationDrive::Kind::time);
  }


  void
  RodModel::fix_loads()
  {
    loads_fixed = true;
  }


  void
  RodModel::follow_natural_shape(const double load_factor) const
  {
    configuration_->follow_activation(load_factor);
    if (given_materials.empty() || load_factor == ramped_at)
      return;
    for (std::size_t rod = 0; rod < given_materials.size(); ++rod)
      if (given_materials[rod])
        materials[rod] =
          given_materials[rod]->with_natural_shape_scaled(ramped_parts,
                                                          load_factor);
    ramped_at = load_factor;
  }
} // namespace rodnet
