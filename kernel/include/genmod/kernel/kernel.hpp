// The public API of the kernel layer.
#pragma once

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/expression.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/inclusion.hpp"
#include "genmod/kernel/input_stages.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/opcode.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/tape_contractor.hpp"
#include "genmod/kernel/vm_format.hpp"
