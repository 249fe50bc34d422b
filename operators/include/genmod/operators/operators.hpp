// The public API of the operators layer: GENMOD's operator library on the kernel.
#pragma once

#include "genmod/operators/branching.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/curve_file.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/operators/matrix.hpp"
#include "genmod/operators/offset.hpp"
#include "genmod/operators/path.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/table.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/operators/warp.hpp"
