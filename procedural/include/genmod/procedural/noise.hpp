// Perlin's Improved Noise (2002), the noise Morkel's random-number class offers beside the Java
// generator (§1.11). Same permutation table and arithmetic order as the reference, so values
// match it to the bit (claim 8); zero at every integer lattice point.
#pragma once

namespace genmod {

double improved_noise(double x, double y, double z);

}  // namespace genmod
