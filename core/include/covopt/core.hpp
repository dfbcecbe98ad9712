#pragma once
/// @file core.hpp
/// Everything of covopt::core: scene, values with units, force law, exact path, time path.
#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/core/sensitivity.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/core/sweep.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/core/work_precision.hpp"
