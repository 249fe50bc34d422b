// The procedure layer: registered procedures with defaults, context and caching, reproducible
// randomness (Java's LCG, Perlin's improved noise) and mesh content hashes.
#pragma once

#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/mesh_hash.hpp"
#include "genmod/procedural/noise.hpp"
#include "genmod/procedural/procedure.hpp"
#include "genmod/procedural/rng.hpp"
