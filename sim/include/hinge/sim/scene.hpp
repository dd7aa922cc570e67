// hinge/sim/scene.hpp: the scene the simulator runs. The format, its types and its strict reader are
// hinge::io's (hinge/io/scene.hpp); the simulator takes them by these names.
#pragma once

#include "hinge/io/scene.hpp"

namespace hinge::sim {

using io::Bending;
using io::Damping;
using io::Gravity;
using io::HessianTreatment;
using io::LinearSolver;
using io::Load;
using io::Material;
using io::Mode;
using io::Pins;
using io::read_scene;
using io::Scene;
using io::Solve;
using io::Sphere;
using io::Stretching;
using io::Vec3;

}  // namespace hinge::sim
