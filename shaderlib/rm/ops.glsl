// rm/ops.glsl: combining distances. Booleans, their smooth, chamfered and
// rounded variants, and RmHit, a distance that carries a material id.
// Provides: opUnion, opIntersection, opSubtraction, opSmoothUnion,
//   opSmoothIntersection, opSmoothSubtraction, opSmoothUnionBlend,
//   opSmoothIntersectionBlend, opSmoothSubtractionBlend, opChamferUnion,
//   opChamferIntersection, opChamferSubtraction, opRoundUnion,
//   opRoundIntersection, opRoundSubtraction, RmHit, rmHit, rmHitBlend,
//   rmBlendHits.
// Needs: nothing.
// Classes: with exact inputs, a union is exact outside and a bound inside;
// intersection and subtraction are bounds, and so are the smooth variants
// (their gradient is a convex mix of the inputs' gradients). Chamfer and round
// variants are bounds where the surfaces meet at right angles; in general
// their Lipschitz constant is up to sqrt(2): scale by 0.7071 to be safe.
// Radii k, r of zero give the sharp operation, never NaN.
// opSubtraction(a, b) is "a minus b".
#ifndef RM_OPS_GLSL
#define RM_OPS_GLSL

// Union of the shapes a and b. exact outside for exact inputs, else bound
float opUnion(float a, float b) { return min(a, b); }

// Intersection of a and b. bound
float opIntersection(float a, float b) { return max(a, b); }

// a with b cut away. bound
float opSubtraction(float a, float b) { return max(a, -b); }

// Smooth union over a blend width k, with the blend factor: returns
// (distance, w) where w in [0, 1] is b's weight, for mixing materials. bound
vec2 opSmoothUnionBlend(float a, float b, float k) {
  // iq's quadratic polynomial smooth minimum, written so that k = 0 is min().
  float h = k > 0.0 ? max(k - abs(a - b), 0.0) / k : 0.0;
  float d = min(a, b) - 0.25 * k * h * h;
  float w = 0.5 * h;  // weight of the farther shape
  return vec2(d, a < b ? w : 1.0 - w);
}

// Smooth union over a blend width k. bound
float opSmoothUnion(float a, float b, float k) { return opSmoothUnionBlend(a, b, k).x; }

// Smooth intersection over width k, with b's weight as y. bound
vec2 opSmoothIntersectionBlend(float a, float b, float k) {
  vec2 u = opSmoothUnionBlend(-a, -b, k);
  return vec2(-u.x, u.y);
}

// Smooth intersection over a blend width k. bound
float opSmoothIntersection(float a, float b, float k) { return opSmoothIntersectionBlend(a, b, k).x; }

// Smooth a-minus-b over width k, with b's weight as y. bound
vec2 opSmoothSubtractionBlend(float a, float b, float k) { return opSmoothIntersectionBlend(a, -b, k); }

// Smooth a-minus-b over a blend width k. bound
float opSmoothSubtraction(float a, float b, float k) { return opSmoothSubtractionBlend(a, b, k).x; }

// Union with a 45-degree chamfer of size r along the seam. approximate, Lipschitz sqrt(2)
float opChamferUnion(float a, float b, float r) { return min(min(a, b), (a + b - r) * 0.70710678); }

// Intersection with a 45-degree chamfer of size r along the seam. approximate, Lipschitz sqrt(2)
float opChamferIntersection(float a, float b, float r) { return max(max(a, b), (a + b + r) * 0.70710678); }

// a minus b with a 45-degree chamfer of size r. approximate, Lipschitz sqrt(2)
float opChamferSubtraction(float a, float b, float r) { return opChamferIntersection(a, -b, r); }

// Union with a quarter-circle fillet of radius r along the seam. approximate, Lipschitz sqrt(2)
float opRoundUnion(float a, float b, float r) {
  vec2 u = max(vec2(r - a, r - b), 0.0);
  return max(r, min(a, b)) - length(u);
}

// Intersection with a rounded seam of radius r. approximate, Lipschitz sqrt(2)
float opRoundIntersection(float a, float b, float r) {
  vec2 u = max(vec2(r + a, r + b), 0.0);
  return min(-r, max(a, b)) + length(u);
}

// a minus b with a rounded seam of radius r. approximate, Lipschitz sqrt(2)
float opRoundSubtraction(float a, float b, float r) { return opRoundIntersection(a, -b, r); }

// A distance d with material ids: where a smooth op blends two materials, id
// is the dominant one, id2 the other and blend (0..0.5) the share of id2.
// map() can return rmHit(...).d: unused id fields compile away.
struct RmHit {
  float d;
  float id;
  float id2;
  float blend;
};

// A hit of one material.
RmHit rmHit(float d, float id) { return RmHit(d, id, id, 0.0); }

// Mix of two per-material values by a hit's blend: rmHitBlend(h, col(h.id), col(h.id2)).
vec3 rmHitBlend(RmHit h, vec3 a, vec3 b) { return mix(a, b, h.blend); }

// The nearer of two hits. distance class as opUnion
RmHit opUnion(RmHit a, RmHit b) { return a.d < b.d ? a : b; }

// Intersection; the material of the surface that bounds it. bound
RmHit opIntersection(RmHit a, RmHit b) { return a.d > b.d ? a : b; }

// a minus b; the cut face takes b's material. bound
RmHit opSubtraction(RmHit a, RmHit b) { return a.d > -b.d ? a : RmHit(-b.d, b.id, b.id2, b.blend); }

// Turns a blended distance (d, weight of b) into a hit that carries both ids.
RmHit rmBlendHits(vec2 dw, RmHit a, RmHit b) {
  return dw.y < 0.5 ? RmHit(dw.x, a.id, b.id, dw.y) : RmHit(dw.x, b.id, a.id, 1.0 - dw.y);
}

// Smooth union of hits over width k; the materials blend across the seam. bound
RmHit opSmoothUnion(RmHit a, RmHit b, float k) { return rmBlendHits(opSmoothUnionBlend(a.d, b.d, k), a, b); }

// Smooth intersection of hits over width k. bound
RmHit opSmoothIntersection(RmHit a, RmHit b, float k) {
  return rmBlendHits(opSmoothIntersectionBlend(a.d, b.d, k), a, b);
}

// Smooth a-minus-b of hits over width k. bound
RmHit opSmoothSubtraction(RmHit a, RmHit b, float k) {
  return rmBlendHits(opSmoothSubtractionBlend(a.d, b.d, k), a, b);
}

#endif  // RM_OPS_GLSL
