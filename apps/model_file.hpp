// Loading the model files the commands take.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/models/gallery.hpp"

#include <string>

namespace genmod::app {

// A .vm model; std::runtime_error (naming the path) if it cannot be read or parsed.
Fn load_model(const std::string& path);

// An implicit model by name: an implicit gallery model (with `overrides` of its parameters;
// UsageError for a bad one) or else a .vm file. `overrides` must be empty for a file.
Fn load_implicit_model(const std::string& name, const models::ParameterValues& overrides = {});

// A model of x and y only, compiled with inputs (x, y); std::runtime_error naming the path
// and the extra coordinate otherwise.
Tape load_planar_model(const std::string& path);

}  // namespace genmod::app
