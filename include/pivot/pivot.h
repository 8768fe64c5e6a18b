// pivot2d: a 2D rigid-body physics library whose revolute joints each choose their own
// position-correction algorithm. Include this one header for the whole public API.
#pragma once

#include "pivot/body.h"
#include "pivot/broad_phase_boxes.h"
#include "pivot/constants.h"
#include "pivot/continuous_collision.h"
#include "pivot/debug_draw.h"
#include "pivot/error.h"
#include "pivot/id.h"
#include "pivot/joint.h"
#include "pivot/math.h"
#include "pivot/query.h"
#include "pivot/shape.h"
#include "pivot/solvers.h"
#include "pivot/step_tasks.h"
#include "pivot/world.h"
