#pragma once
// A grey window over HU: what the MIP, the CPR and the slice view display through. Grey =
// clamp((HU - (level - window / 2)) / window, 0, 1).
namespace angio {

struct WindowLevel {
  double window = 800;  // HU; the contrast-filled lumen against soft tissue
  double level = 250;   // HU

  friend bool operator==(const WindowLevel&, const WindowLevel&) = default;
};

}  // namespace angio
