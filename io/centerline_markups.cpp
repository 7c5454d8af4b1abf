#include "io/centerline_markups.h"

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "io/json_text.h"
#include "io/input_error.h"
#include "io/shown_text.h"
#include "io/lowercase.h"

namespace angio {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

namespace {

std::string stringOr(const Json& object, const char* key, const std::string& fallback) {
  const auto found = object.find(key);
  return found != object.end() && found->is_string() ? found->get<std::string>() : fallback;
}

// How one markup's coordinates map to LPS millimetres.
struct CoordinateMapping {
  glm::dvec3 axisSigns{1.0};  // RAS -> LPS flips x and y
  double toMm = 1.0;
};

CoordinateMapping coordinateMapping(const Json& markup, const fs::path& source,
                                    const std::string& where) {
  CoordinateMapping mapping;
  const std::string system = stringOr(markup, "coordinateSystem", "LPS");
  if (system == "RAS") {
    mapping.axisSigns = {-1.0, -1.0, 1.0};
  } else if (system != "LPS") {
    throw InputError(source, where + ": unknown coordinateSystem " + quotedText(system));
  }
  // Units are a string ("mm") or a DICOM code triple (["mm", "UCUM", "millimeter"]).
  std::string units = "mm";
  if (const auto found = markup.find("coordinateUnits"); found != markup.end()) {
    const Json& code = found->is_array() && !found->empty() ? found->front() : *found;
    units = code.is_string() ? code.get<std::string>() : "?";
  }
  if (units == "um") {
    mapping.toMm = 1e-3;
  } else if (units != "mm") {
    throw InputError(source, where + ": unknown coordinateUnits " + quotedText(units));
  }
  return mapping;
}

double number(const Json& value, const fs::path& source, const std::string& what) {
  if (!value.is_number()) throw InputError(source, what + " is not a number: " + value.dump());
  return value.get<double>();
}

// The per-control-point values of the "Radius" measurement, if there is one.
std::optional<std::vector<double>> radiusValues(const Json& markup, std::size_t controlPoints,
                                                const fs::path& source, const std::string& where) {
  const auto measurements = markup.find("measurements");
  if (measurements == markup.end() || !measurements->is_array()) return std::nullopt;
  for (const Json& measurement : *measurements) {
    if (!measurement.is_object() || lowercase(stringOr(measurement, "name", "")) != "radius") continue;
    const auto values = measurement.find("controlPointValues");
    if (values == measurement.end() || !values->is_array()) continue;
    if (values->size() != controlPoints) {
      throw InputError(source, where + ": Radius measurement has " + std::to_string(values->size()) +
                                   " values for " + std::to_string(controlPoints) + " control points");
    }
    std::vector<double> radii;
    for (std::size_t n = 0; n < values->size(); ++n) {
      radii.push_back(number((*values)[n], source, where + ": Radius value " + std::to_string(n)));
    }
    return radii;
  }
  return std::nullopt;
}

glm::dvec3 position(const Json& controlPoint, const fs::path& source, const std::string& where) {
  const auto found = controlPoint.find("position");
  if (found == controlPoint.end() || !found->is_array() || found->size() != 3) {
    throw InputError(source, where + ": position is not an array of 3 numbers");
  }
  return {number((*found)[0], source, where + ": x"), number((*found)[1], source, where + ": y"),
          number((*found)[2], source, where + ": z")};
}

CenterlinePath readCurve(const Json& markup, std::size_t index, const fs::path& source,
                         const CenterlineLoadOptions& options) {
  CenterlinePath path{stringOr(markup, "name", ""), {}};
  if (path.name.empty()) path.name = std::to_string(index);
  const std::string where = "markup " + quotedText(path.name);
  const CoordinateMapping mapping = coordinateMapping(markup, source, where);

  const Json noPoints = Json::array();
  const auto found = markup.find("controlPoints");
  const Json& controlPoints = found != markup.end() ? *found : noPoints;
  if (!controlPoints.is_array()) throw InputError(source, where + ": controlPoints is not an array");
  const std::optional<std::vector<double>> radii =
      radiusValues(markup, controlPoints.size(), source, where);

  std::size_t undefined = 0;
  for (std::size_t n = 0; n < controlPoints.size(); ++n) {
    const Json& controlPoint = controlPoints[n];
    const std::string pointWhere = where + " control point " + std::to_string(n);
    if (!controlPoint.is_object()) throw InputError(source, pointWhere + " is not an object");
    if (stringOr(controlPoint, "positionStatus", "defined") == "undefined") {
      ++undefined;
      continue;
    }
    const glm::dvec3 lps = position(controlPoint, source, pointWhere) * mapping.axisSigns;
    path.points.push_back({lps * mapping.toMm, radii ? (*radii)[n] : 0.0});
  }
  if (undefined > 0 && options.warn) {
    options.warn(source.string() + ": " + where + ": skipped " + std::to_string(undefined) +
                 " control points without a position");
  }
  return path;
}

// --- Writing ------------------------------------------------------------------------------------

// Slicer reads any markups-schema-v1.x.y; this is the version whose fields are written here.
constexpr const char* kSchema =
    "https://raw.githubusercontent.com/slicer/slicer/main/Modules/Loadable/Markups/Resources/Schema/"
    "markups-schema-v1.0.3.json#";

OrderedJson controlPointJson(const CenterlinePath& path, std::size_t index) {
  const glm::dvec3& p = path.points[index].positionMm;
  const std::string id = std::to_string(index + 1);
  return {{"id", id},
          {"label", path.name + "-" + id},  // Slicer's default label format, "%N-%d"
          {"position", OrderedJson::array({p.x, p.y, p.z})},
          // The identity in RAS, written in LPS as Slicer writes it (its first two rows negated).
          {"orientation", OrderedJson::array({-1.0, -0.0, -0.0, -0.0, -1.0, -0.0, 0.0, 0.0, 1.0})},
          {"selected", true},
          {"locked", false},
          {"visibility", true},
          {"positionStatus", "defined"}};
}

// SlicerVMTK's centerline curves carry the lumen radius as a static per-point measurement
// (vtkMRMLStaticMeasurement: enabled, units mm, no value, no print format).
OrderedJson radiusJson(const CenterlinePath& path) {
  OrderedJson radii = OrderedJson::array();
  for (const CenterlinePoint& point : path.points) radii.push_back(point.radiusMm);
  return {{"name", "Radius"}, {"enabled", true}, {"units", "mm"}, {"controlPointValues", radii}};
}

OrderedJson curveJson(const CenterlinePath& path) {
  OrderedJson controlPoints = OrderedJson::array();
  for (std::size_t n = 0; n < path.points.size(); ++n)
    controlPoints.push_back(controlPointJson(path, n));
  return {{"type", "Curve"},
          {"name", path.name},
          {"coordinateSystem", "LPS"},
          {"coordinateUnits", "mm"},
          {"locked", false},
          {"fixedNumberOfControlPoints", false},
          {"labelFormat", "%N-%d"},
          {"lastUsedControlPointNumber", path.points.size()},
          {"controlPoints", controlPoints},
          {"measurements", OrderedJson::array({radiusJson(path)})}};
}

// Objects and arrays that hold objects are spread one member per line; everything else (a control
// point, a position, the radius values) stays on one line, as in Slicer's own files. dump(2) would
// give every number a line of its own.
bool holdsObjects(const OrderedJson& value) {
  for (const OrderedJson& member : value) {
    if (member.is_object() || (member.is_array() && !member.empty() && member.front().is_object())) {
      return true;
    }
  }
  return false;
}

void appendLaidOut(const OrderedJson& value, const std::string& indent, std::string& out) {
  // Invalid UTF-8 in a name is replaced rather than throwing halfway through a save (as tf_file).
  const auto compact = [](const OrderedJson& json) {
    return json.dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
  };
  if (!value.is_structured() || !holdsObjects(value)) {
    out += compact(value);
    return;
  }
  const std::string inner = indent + "  ";
  out += value.is_object() ? "{\n" : "[\n";
  std::size_t left = value.size();
  for (auto member = value.begin(); member != value.end(); ++member) {
    out += inner;
    if (value.is_object()) out += compact(member.key()) + ": ";
    appendLaidOut(*member, inner, out);
    out += --left > 0 ? ",\n" : "\n";
  }
  out += indent + (value.is_object() ? "}" : "]");
}

std::string markupsText(const Centerlines& centerlines) {
  OrderedJson markups = OrderedJson::array();
  for (const CenterlinePath& path : centerlines.paths) markups.push_back(curveJson(path));
  std::string text;
  appendLaidOut({{"@schema", kSchema}, {"markups", markups}}, "", text);
  return text + "\n";
}

}  // namespace

void writeCenterlinesMarkups(const Centerlines& centerlines, const fs::path& file) {
  requirePhysicalFrame(centerlines, "a Slicer markups file");
  writeBytesAtomically(file, markupsText(centerlines));
}

Centerlines parseCenterlinesMarkups(const std::string& text, const fs::path& source,
                                    const CenterlineLoadOptions& options) {
  const Json json = parseJsonText(text, source);
  const auto markups = json.is_object() ? json.find("markups") : json.end();
  if (!json.is_object() || markups == json.end() || !markups->is_array()) {
    throw InputError(source, "not a markups file (no \"markups\" array)");
  }
  Centerlines centerlines;
  centerlines.source = source.string();
  for (std::size_t index = 0; index < markups->size(); ++index) {
    const Json& markup = (*markups)[index];
    if (!markup.is_object())
      throw InputError(source, "markup " + std::to_string(index) + " is not an object");
    const std::string type = stringOr(markup, "type", "");
    if (type == "Curve" || type == "Line") {
      centerlines.paths.push_back(readCurve(markup, index, source, options));
    } else if (options.warn) {
      options.warn(source.string() + ": markup " + std::to_string(index) + " of type " +
                   quotedText(type) + " is not a curve; skipped");
    }
  }
  checkLoadedCenterlines(centerlines, source, options);
  return centerlines;
}

Centerlines readCenterlinesMarkups(const fs::path& file, const CenterlineLoadOptions& options) {
  return parseCenterlinesMarkups(readCenterlineFileBytes(file), file, options);
}

}  // namespace angio
