#pragma once
/// @file materials.hpp
/// Everything of covopt::materials: the Material entry and the Catalog (built-in, from
/// TOML, lookup, suggestions, filters), and ISO/TS 15066's body-region table.
#include "covopt/materials/body_regions.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/materials/material.hpp"
