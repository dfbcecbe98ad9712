#pragma once
/// @file optim.hpp
/// Everything of covopt::optim: the Problem interface and its NLopt/Ipopt backends, the
/// impact oracles, the covering-design problems, the one-call design request of `covopt
/// optimize`, the maximum safe speed and mass of `covopt speed-limit` and its table, the
/// trajectory check, the robust design over an uncertainty box, the input warnings, and the
/// time-optimal parameterisation of a path.
#include "covopt/optim/backends.hpp"
#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/design_map.hpp"
#include "covopt/optim/design_work_precision.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/problem.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/optim/time_optimal_path.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/optim/verdicts.hpp"
