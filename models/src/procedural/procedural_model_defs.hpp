// One definition per procedural model source file: the procedure's spec and what `genmod list`
// prints about it.
#pragma once

#include "genmod/models/procedural_models.hpp"

namespace genmod::models::detail {

struct ProceduralModelDef {
  ProcedureSpec spec;
  ProceduralModel info;
};

ProceduralModelDef leg_definition();
ProceduralModelDef chair_definition();
ProceduralModelDef couch_definition();
ProceduralModelDef table_definition();
ProceduralModelDef luggage_definition();
ProceduralModelDef luggage_chest_definition();
ProceduralModelDef foot_definition();
ProceduralModelDef arm_definition();
ProceduralModelDef torso_definition();
ProceduralModelDef head_definition();
ProceduralModelDef human_definition();
ProceduralModelDef branch_definition();
ProceduralModelDef tree_definition();

}  // namespace genmod::models::detail
