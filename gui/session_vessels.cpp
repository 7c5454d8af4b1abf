#include "gui/session_vessels.h"

#include <cmath>
#include <string>

#include "io/input_error.h"

namespace angio {

namespace {

using Json = nlohmann::json;

Json pointJson(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

Json pathJson(const VesselPath& path) {
  Json controls = Json::array(), points = Json::array();
  for (const glm::dvec3& p : path.controlPointsMm) controls.push_back(pointJson(p));
  for (const CenterlinePoint& p : path.centerline.points)
    points.push_back({p.positionMm.x, p.positionMm.y, p.positionMm.z, p.radiusMm});
  return {{"name", path.name}, {"control_points_mm", controls}, {"points", points}};
}

struct VesselsReader {
  const std::filesystem::path& source;

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(source, "vessels" + where + " " + problem);
  }
  // [x, y, z] or, with `withRadius`, [x, y, z, r]: finite numbers.
  std::vector<double> numbers(const Json& value, std::size_t count, const std::string& where) const {
    if (!value.is_array() || value.size() != count)
      fail(where, "is not a list of " + std::to_string(count) + " numbers");
    std::vector<double> n;
    for (const Json& x : value) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) fail(where, "holds a non-number");
      n.push_back(x.get<double>());
    }
    return n;
  }
  const Json& list(const Json& object, const char* key, const std::string& where) const {
    if (!object.contains(key) || !object[key].is_array()) fail(where + "." + key, "is not a list");
    return object[key];
  }
  VesselPath path(const Json& json, const std::string& where) const {
    if (!json.is_object()) fail(where, "is not an object");
    VesselPath path;
    if (!json.contains("name") || !json["name"].is_string()) fail(where + ".name", "is not a string");
    path.name = json["name"].get<std::string>();
    path.centerline.name = path.name;
    const Json& controls = list(json, "control_points_mm", where);
    for (std::size_t n = 0; n < controls.size(); ++n) {
      const std::vector<double> p =
          numbers(controls[n], 3, where + ".control_points_mm[" + std::to_string(n) + "]");
      path.controlPointsMm.push_back({p[0], p[1], p[2]});
    }
    const Json& points = list(json, "points", where);
    for (std::size_t n = 0; n < points.size(); ++n) {
      const std::vector<double> p = numbers(points[n], 4, where + ".points[" + std::to_string(n) + "]");
      if (p[3] < 0) fail(where + ".points[" + std::to_string(n) + "]", "has a negative radius");
      path.centerline.points.push_back({{p[0], p[1], p[2]}, p[3]});
    }
    return path;
  }
};

}  // namespace

Json vesselsJson(const VesselsState& vessels) {
  Json paths = Json::array();
  for (const VesselPath& path : vessels.paths) paths.push_back(pathJson(path));
  return {{"file", vessels.file}, {"unsaved", vessels.unsaved}, {"paths", paths}};
}

VesselsState parseVessels(const Json& json, const std::filesystem::path& source) {
  const VesselsReader reader{source};
  if (!json.is_object()) reader.fail("", "is not an object");
  VesselsState vessels;
  if (json.contains("file")) {
    if (!json["file"].is_string()) reader.fail(".file", "is not a string");
    vessels.file = json["file"].get<std::string>();
  }
  if (json.contains("unsaved")) {
    if (!json["unsaved"].is_boolean()) reader.fail(".unsaved", "is not true or false");
    vessels.unsaved = json["unsaved"].get<bool>();
  }
  if (!json.contains("paths")) return vessels;
  const Json& paths = reader.list(json, "paths", "");
  for (std::size_t n = 0; n < paths.size(); ++n)
    vessels.paths.push_back(reader.path(paths[n], ".paths[" + std::to_string(n) + "]"));
  return vessels;
}

}  // namespace angio
