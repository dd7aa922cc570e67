// The files embedded at build time (view/CMakeLists.txt: the page's template from page/, three.js and its
// orbit controls from Debian's libjs-three): each is the bytes between hinge_view_NAME_begin and _end.
#pragma once

#include <string_view>

#define HINGE_VIEW_EMBEDDED(name) extern "C" const char hinge_view_##name##_begin[], hinge_view_##name##_end[];
HINGE_VIEW_EMBEDDED(page_html)
HINGE_VIEW_EMBEDDED(page_css)
HINGE_VIEW_EMBEDDED(page_js)
HINGE_VIEW_EMBEDDED(three_notice)
HINGE_VIEW_EMBEDDED(three_js)
HINGE_VIEW_EMBEDDED(orbit_controls_js)
#undef HINGE_VIEW_EMBEDDED

namespace hinge::view::embedded {

#define HINGE_VIEW_FILE(name) \
  inline std::string_view name() { return {hinge_view_##name##_begin, hinge_view_##name##_end}; }
HINGE_VIEW_FILE(page_html)
HINGE_VIEW_FILE(page_css)
HINGE_VIEW_FILE(page_js)
HINGE_VIEW_FILE(three_notice)
HINGE_VIEW_FILE(three_js)
HINGE_VIEW_FILE(orbit_controls_js)
#undef HINGE_VIEW_FILE

}  // namespace hinge::view::embedded
