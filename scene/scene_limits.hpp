// What a scene file may hold. Far beyond any real scene, and each with its own error, so that a
// broken or hostile file stops with one line instead of exhausting the stack or memory (the
// parser, the Lipschitz analysis, the compiler and the interpreter walk the shape tree
// recursively).
#pragma once

#include <cstddef>
#include <cstdint>

namespace lab::scene {

constexpr std::uintmax_t kMaxSceneFileBytes = 16u << 20;  // 16 MiB
// Objects and arrays open at once anywhere in the document; a shape node takes 2 (child) or 3
// (children[i]) levels, so this allows shape trees well over 100 nodes deep.
constexpr size_t kMaxJsonNesting = 400;
// Shape nodes over all objects: every node becomes code in the scene's kernel.
constexpr size_t kMaxShapeNodes = 20000;

}  // namespace lab::scene
