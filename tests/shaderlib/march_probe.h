// A probe that marches rays: its prelude defines map() and trace(ro, rd),
// which runs rmMarch and returns (t, steps, outcome + 10 * ground, tolerance);
// decode_trace unpacks that.
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace rm::test {

// rmMarch's outcomes (RM_HIT, RM_MISS, RM_OUT_OF_STEPS in rm/march.glsl).
constexpr int kHit = 0, kMiss = 1, kOutOfSteps = 2;

struct Traced {
  double t;
  int steps, outcome;
  bool ground;
  double tolerance;
};

// map() returns `map_body` (which may use `vec3 cell`, for opRepeat); trace()
// marches with rmMarchSettings() changed by `settings` (GLSL statements on `s`).
inline std::string march_prelude(const std::string& map_body, const std::string& settings) {
  return "#include <rm/march.glsl>\n#include <rm/normals.glsl>\n#include <rm/sdf.glsl>\n#include <rm/ops.glsl>\n"
         "#include <rm/transforms.glsl>\nvec3 cell;\nfloat map(vec3 p) { return " + map_body + "; }\n"
         "vec4 trace(vec3 ro, vec3 rd) {\n  RmMarchSettings s = rmMarchSettings();\n  " + settings + "\n"
         "  RmMarch m = rmMarch(ro, rd, s);\n"
         "  return vec4(m.t, float(m.steps), float(m.outcome) + (m.ground ? 10.0 : 0.0), m.tolerance);\n}\n";
}

inline Traced decode_trace(const glm::vec4& v) {
  const int code = static_cast<int>(v.z);
  return {v.x, static_cast<int>(v.y), code % 10, code >= 10, v.w};
}

}  // namespace rm::test
