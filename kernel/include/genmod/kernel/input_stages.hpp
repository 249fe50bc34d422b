// Splitting a function by the inputs its parts depend on (Snyder's subfunction tables, §4.2.1;
// research/snyder.md §6.2): a tape-level compiler pass, so that evaluators of structured point
// sets (a lattice, a kd-tree's grid) compute each subexpression once per combination of the
// inputs it really depends on instead of once per point.
//
// Every node of f is put in the stage of its input set (the coordinates it depends on). A
// stage is one tape computing the stage's nodes that something else reads (a node of another
// stage, or a component of f); its inputs are its own coordinates and, as placeholder inputs,
// the outputs of lower stages it reads. The stage's nodes are rebuilt over those placeholders
// with the operations and operand order of the original DAG, so a stage computes bitwise what
// the whole function's tape computes for those nodes. Where the DAG's construction rules would
// not reproduce that (min / max operands reordered), or there are more lower-stage operands
// than unused coordinates to stand for them, the stage is compiled from its original nodes
// instead (reading only coordinates: still exact, only not sharing the lower stages' work),
// and counted in fallback_stages.
//
// Example:
//   using namespace genmod;
//   Fn f = sin(x(0)) * cos(x(1)) + x(0);  // sin(x0) depends on x0 alone, cos(x1) on x1 alone
//   StagedFunction s = stage_by_inputs(f);
//   // s.stages: {x0}: sin(x0); {x1}: cos(x1); {x0, x1}: the product and the sum, reading the
//   // first two stages' outputs; s.components[0] names the last stage's output 0
//   if (s.stages.size() != 3 || s.components[0].kind != StageSource::Kind::Stage) throw std::logic_error("stages");
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace genmod {

// Where a stage's tape input, or a component of the function, takes its values from.
struct StageSource {
  enum class Kind { Coordinate, Stage, Constant };
  Kind kind = Kind::Constant;
  int coordinate = -1;                // Coordinate: x(coordinate)
  std::size_t stage = 0, output = 0;  // Stage: output `output` of stages[stage]
  double value = 0.0;                 // Constant: this number
};

struct InputStage {
  // The coordinates its outputs depend on (bit c = x(c)); 0 for numbers the DAG does not fold
  // (a custom operator applied to constants).
  std::uint64_t inputs = 0;
  Tape tape;                 // its outputs, the nodes of this input set that are read elsewhere
  // Per tape input, in the tape's input order: a coordinate in `inputs`, or the output of an
  // earlier stage, whose input set is a proper subset of `inputs`.
  std::vector<StageSource> sources;
};

struct StagedFunction {
  // Every stage reads only stages before it; stages with fewer inputs come first.
  std::vector<InputStage> stages;
  std::vector<StageSource> components;  // per component of f: a stage output, x(c) or a number
  std::size_t fallback_stages = 0;      // compiled from their original nodes (see above)
};

StagedFunction stage_by_inputs(const Fn& f);

}  // namespace genmod
