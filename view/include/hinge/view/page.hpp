// hinge/view/page.hpp: the page of `hinge view` (docs/view.md; docs/contract.md, `hinge view`): one
// self-contained HTML file that plays a run's frames in 3D, each hinge coloured by |theta - theta_bar| on one
// scale for all frames (a colour bar in radians), with play, pause, a frame slider showing the time, orbit and
// zoom, and the scene's sphere. It draws with WebGL through three.js (Debian's libjs-three, embedded), or on a
// plain 2D canvas where WebGL is unavailable. Nothing in it loads anything from elsewhere: its
// Content-Security-Policy forbids every fetch, and it holds no address of a resource.
#pragma once

#include <iosfwd>

#include "hinge/view/run.hpp"

namespace hinge::view {

// The figures the page is made of (for messages and tests).
struct PageStats {
  std::size_t frames = 0, hinges = 0;
  double scale = 0;  // the colour bar's top: the largest |theta - theta_bar| over all frames (radians), 1 if none
};

// Writes the page for `run` to `out`: each hinge's |theta - theta_bar| per frame, theta_bar on run.rest
// (bending.hpp), the positions and values encoded as encoding.hpp says. Throws hinge::InputError naming
// rest.obj when the rest shape is not a valid mesh (non-manifold, inconsistently oriented).
PageStats write_page(std::ostream& out, const Run& run);

}  // namespace hinge::view
