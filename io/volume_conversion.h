#pragma once
// Per-voxel conversions of the volume reader, templated on the stored component type so the hot
// loops have no per-voxel dispatch: HU -> 12-bit density (rendering model's encoding, with NaN/Inf
// rejected as -1024 HU) and label values -> 4-bit labels.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>

#include <itkImageIOBase.h>

#include "core/voxel.h"

namespace angio {

// Calls f(std::type_identity<T>{}) with T the C++ type of an ITK component type.
template <class F>
decltype(auto) withComponentType(itk::IOComponentEnum type, F&& f) {
  using C = itk::IOComponentEnum;
  switch (type) {
    case C::UCHAR: return f(std::type_identity<unsigned char>{});
    case C::CHAR: return f(std::type_identity<signed char>{});
    case C::USHORT: return f(std::type_identity<unsigned short>{});
    case C::SHORT: return f(std::type_identity<short>{});
    case C::UINT: return f(std::type_identity<unsigned int>{});
    case C::INT: return f(std::type_identity<int>{});
    case C::ULONG: return f(std::type_identity<unsigned long>{});
    case C::LONG: return f(std::type_identity<long>{});
    case C::ULONGLONG: return f(std::type_identity<unsigned long long>{});
    case C::LONGLONG: return f(std::type_identity<long long>{});
    case C::FLOAT: return f(std::type_identity<float>{});
    case C::DOUBLE: return f(std::type_identity<double>{});
    default: throw std::invalid_argument("unsupported voxel component type");
  }
}

// d = clamp(round(HU) + 1024, 0, 4095); integers skip the rounding and never overflow.
template <class T>
inline Voxel densityVoxel(T hu, std::size_t& nonFinite) {
  constexpr long long lowest = -kHuOffset, highest = kDensityLevels - 1 - kHuOffset;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(hu)) {
      ++nonFinite;
      return encodeVoxel(-kHuOffset);
    }
    return static_cast<Voxel>(densityOfHu(double(hu)));
  } else if constexpr (std::is_unsigned_v<T>) {
    return static_cast<Voxel>(std::min<unsigned long long>(hu, highest) + kHuOffset);
  } else {
    return static_cast<Voxel>(std::clamp<long long>(hu, lowest, highest) + kHuOffset);
  }
}

// Row converter for reorientCopy: HU values -> voxels; returns the number of NaN/Inf values.
struct HuToVoxels {
  template <class T>
  std::size_t operator()(const T* first, std::ptrdiff_t step, int count, Voxel* out) const {
    std::size_t nonFinite = 0;
    if (step == 1) {  // the common, unflipped case: let the compiler vectorise
      for (int x = 0; x < count; ++x) out[x] = densityVoxel(first[x], nonFinite);
    } else {
      for (int x = 0; x < count; ++x) out[x] = densityVoxel(first[x * step], nonFinite);
    }
    return nonFinite;
  }
};

// Row converter for reorientCopy: label values -> 0..15; returns how many were not among `valid`
// (outside 0..15, not whole numbers, or a value `valid` leaves out); those read as 0.
struct ToLabels {
  std::array<bool, kMaxLabel + 1> valid = everyLabel();

  static constexpr std::array<bool, kMaxLabel + 1> everyLabel() {
    std::array<bool, kMaxLabel + 1> all{};
    all.fill(true);
    return all;
  }

  template <class T>
  std::size_t operator()(const T* first, std::ptrdiff_t step, int count, std::uint8_t* out) const {
    std::size_t invalid = 0;
    for (int x = 0; x < count; ++x) {
      const T value = first[x * step];
      const bool isLabel =
          value >= T(0) && value <= T(kMaxLabel) && value == T(int(value)) && valid[std::size_t(value)];
      out[x] = isLabel ? static_cast<std::uint8_t>(value) : 0;
      invalid += !isLabel;
    }
    return invalid;
  }
};

// Row converter for reorientCopy: a plain copy (voxels already encoded).
struct CopyRow {
  template <class T>
  std::size_t operator()(const T* first, std::ptrdiff_t step, int count, T* out) const {
    for (int x = 0; x < count; ++x) out[x] = first[x * step];
    return 0;
  }
};

}  // namespace angio
