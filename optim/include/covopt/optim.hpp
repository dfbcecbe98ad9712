#pragma once
/// @file optim.hpp
/// Everything of covopt::optim: the Problem interface and its NLopt/Ipopt backends, the
/// covering-design problems, the one-call design request of `covopt optimize`, and the maximum
/// safe speed and mass of `covopt speed-limit`.
#include "covopt/optim/backends.hpp"
#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/problem.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/trajectory_check.hpp"
