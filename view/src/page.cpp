// The page of `hinge view` (hinge/view/page.hpp): the run's data as JSON inside the template (page/), with
// three.js and its orbit controls.
#include "hinge/view/page.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "embedded.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/view/bending.hpp"
#include "hinge/view/encoding.hpp"

namespace hinge::view {

namespace {

using json = nlohmann::json;

Topology rest_topology(const Run& run) {
  try {
    return build_topology(run.rest);
  } catch (const InputError& e) {
    throw InputError(run.folder + "/rest.obj: " + e.what());
  }
}

// For every face and each of its edges i (v_{i+1} -> v_{i+2}), the hinge on that edge, or -1 on the boundary.
std::vector<std::int32_t> face_hinges(const Topology& t) {
  std::vector<std::int32_t> h(3 * t.faces.size());
  for (std::size_t f = 0; f < t.faces.size(); ++f)
    for (std::size_t i = 0; i < 3; ++i) h[3 * f + i] = t.hinge_of_edge[static_cast<std::size_t>(t.face_edges[f][i])];
  return h;
}

// JSON inside a <script> element: "</" written as "<\/" (the same string to a JSON reader).
std::string script_safe(const std::string& json_text) {
  std::string out;
  out.reserve(json_text.size());
  for (std::size_t i = 0; i < json_text.size(); ++i) {
    out += json_text[i];
    if (json_text[i] == '<' && i + 1 < json_text.size() && json_text[i + 1] == '/') out += '\\';
  }
  return out;
}

// The template with each placeholder replaced by its text, all found in the template itself (so that no text
// put in is searched); a placeholder missing from it is a bug here.
std::string fill(std::string_view page, std::vector<std::pair<std::string_view, std::string_view>> parts) {
  std::vector<std::size_t> at;
  for (const auto& part : parts) {
    at.push_back(page.find(part.first));
    if (at.back() == std::string_view::npos)
      throw std::logic_error("hinge view: the page template lacks " + std::string(part.first));
  }
  std::vector<std::size_t> order(parts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return at[a] < at[b]; });
  std::string out;
  std::size_t done = 0;
  for (const std::size_t i : order) {
    out.append(page.substr(done, at[i] - done));
    out.append(parts[i].second);
    done = at[i] + parts[i].first.size();
  }
  out.append(page.substr(done));
  return out;
}

json vec(const std::array<double, 3>& v) { return json::array({v[0], v[1], v[2]}); }

}  // namespace

PageStats write_page(std::ostream& out, const Run& run) {
  const Topology topology = rest_topology(run);
  const std::vector<double> theta_bar = hinge_angles(topology, run.rest.vertices);

  std::vector<std::vector<double>> values;
  double scale = 0;
  for (const Frame& frame : run.frames) {
    values.push_back(bending_deviation(hinge_angles(topology, frame.vertices), theta_bar));
    for (const double v : values.back())
      if (!std::isnan(v)) scale = std::max(scale, v);
  }
  if (scale == 0) scale = 1;  // no bending anywhere: the bar still has a length

  std::vector<std::vector<Vec3>> positions;
  for (const Frame& frame : run.frames) positions.push_back(frame.vertices);
  const Box box = bounding_box(positions);

  json data;
  data["name"] = run.name;
  data["status"] = run.status;
  data["reason"] = run.reason;
  data["dynamic"] = run.dynamic;
  data["vertices"] = run.rest.vertices.size();
  std::vector<std::int32_t> faces;
  for (const auto& f : run.rest.faces) faces.insert(faces.end(), f.begin(), f.end());
  data["faces"] = base64(faces);
  data["face_hinges"] = base64(face_hinges(topology));
  data["hinges"] = topology.hinges.size();
  data["box"] = {{"min", vec(box.min)}, {"max", vec(box.max)}};
  data["position_levels"] = position_levels;
  data["value_levels"] = value_levels;
  data["scale"] = scale;
  json times = json::array(), frames = json::array(), frame_values = json::array();
  for (std::size_t i = 0; i < run.frames.size(); ++i) {
    times.push_back(run.frames[i].time);
    frames.push_back(base64(quantize_positions(positions[i], box)));
    frame_values.push_back(base64(quantize_values(values[i], scale)));
  }
  data["times"] = std::move(times);
  data["positions"] = std::move(frames);
  data["values"] = std::move(frame_values);
  data["sphere"] = run.sphere ? json{{"center", vec(run.sphere->center)}, {"radius", run.sphere->radius}} : json();
  const bool falls = run.gravity && *run.gravity != io::Vec3{0, 0, 0};  // "up" against gravity, else +z
  data["up"] = falls ? vec({-(*run.gravity)[0], -(*run.gravity)[1], -(*run.gravity)[2]}) : vec({0, 0, 1});

  const std::string data_text = script_safe(data.dump());
  out << fill(embedded::page_html(), {{"/*hinge:style*/", embedded::page_css()},
                                      {"<!--hinge:three-notice-->", embedded::three_notice()},
                                      {"/*hinge:three*/", embedded::three_js()},
                                      {"/*hinge:orbit-controls*/", embedded::orbit_controls_js()},
                                      {"/*hinge:data*/", data_text},
                                      {"/*hinge:page*/", embedded::page_js()}});
  return PageStats{run.frames.size(), topology.hinges.size(), scale};
}

}  // namespace hinge::view
