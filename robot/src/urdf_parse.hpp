#pragma once
/// @file urdf_parse.hpp
/// urdfdom's parse with its console output collected (private to covopt_robot): what
/// KinematicChain and the surface reader share.

#include <string>

#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace covopt::robot::internal {

/// urdfdom's links hold their children by shared_ptr: the links of a cycle (refused by
/// CheckTree) would hold each other and never be freed. Dropping every link's children when
/// the model goes out of use breaks such cycles; the chain keeps nothing of the model.
struct ModelReleaser {
  urdf::ModelInterface* model;
  ~ModelReleaser() {
    if (model == nullptr) return;
    for (const auto& [name, link] : model->links_) {
      if (!link) continue;
      link->child_links.clear();
      link->child_joints.clear();
    }
  }
};

/// Parses URDF text with urdfdom; console_bridge's output is collected, not printed.
/// @throws std::invalid_argument "<source>: malformed URDF: <urdfdom's errors>" in one line.
urdf::ModelInterfaceSharedPtr ParseUrdf(const std::string& text, const std::string& source);

}  // namespace covopt::robot::internal
