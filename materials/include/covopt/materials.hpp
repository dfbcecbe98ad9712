#pragma once
/// @file materials.hpp
/// Everything of covopt::materials: the Material entry and the Catalog (built-in, from
/// TOML, lookup, suggestions, filters).
#include "covopt/materials/catalog.hpp"
#include "covopt/materials/material.hpp"
