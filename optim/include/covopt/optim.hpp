#pragma once
/// @file optim.hpp
/// Everything of covopt::optim: the Problem interface and its NLopt/Ipopt backends, the
/// covering-design problems, and the one-call design request of `covopt optimize`.
#include "covopt/optim/backends.hpp"
#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/problem.hpp"
