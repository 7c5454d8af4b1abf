#pragma once
// The labels that automatic removal writes (rendering-model.md, "Labels"); 3..15 are the user's.
namespace angio {

inline constexpr int kBoneLabel = 1;
inline constexpr int kTableLabel = 2;
inline constexpr int kFirstUserLabel = 3;

}  // namespace angio
