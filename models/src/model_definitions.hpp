// The gallery's model definitions, one per source file, and the parameter lookups they share
// (private to the models library: gallery() is the public way to reach them).
#pragma once

#include "genmod/models/gallery.hpp"

#include <string>

namespace genmod::models {

namespace detail {
// Model definitions, one per source file.
Model doorknob_model();
Model patio_tile_model();
Model lamp_stand_model();
Model tennis_racket_model();
Model briefcase_handle_model();
Model banana_model();
Model turbine_blade_model();
Model gear_model();
Model sphere_cylinder_fillet_model();
Model offsets_model();
Model offset_plate_model();
Model spoon_model();
Model key_model();
Model screwdriver_regular_model();
Model screwdriver_phillips_model();
Model circular_beam_model();
Model time_varying_curve_model();
Model wing_model();
Model furry_bear_model();
Model cross_section_matching_model();
Model cpg_model();
Model cpg_fillet_model();
Model bottle_model();
Model sphere_model();
Model torus_model();
// p.at(name) with a message naming the missing parameter; require_positive also checks > 0.
double param(const ParameterValues& p, const std::string& name);
double require_positive(const ParameterValues& p, const std::string& name);
}  // namespace detail

}  // namespace genmod::models
