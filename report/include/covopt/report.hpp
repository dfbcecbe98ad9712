#pragma once
/// @file report.hpp
/// covopt::report: results as JSON text (the CLI's --json and the Python dicts).
#include "covopt/report/design_json.hpp"
#include "covopt/report/materials_json.hpp"
#include "covopt/report/robot_json.hpp"
#include "covopt/report/simulation_json.hpp"
#include "covopt/report/speed_limit_json.hpp"
#include "covopt/report/trajectory_json.hpp"
