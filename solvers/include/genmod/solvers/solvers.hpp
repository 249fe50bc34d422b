// The public API of the solvers layer.
#pragma once

#include "genmod/solvers/aggregation.hpp"
#include "genmod/solvers/arclength.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/contractor.hpp"
#include "genmod/solvers/implicit_curve.hpp"
#include "genmod/solvers/interval_newton.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "genmod/solvers/limits.hpp"
#include "genmod/solvers/minimize_operator.hpp"
#include "genmod/solvers/minimizer.hpp"
#include "genmod/solvers/offsets.hpp"
#include "genmod/solvers/queries.hpp"
#include "genmod/solvers/solve_operator.hpp"
