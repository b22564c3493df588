// common/core/torus_frame.inl — the torus's local frame at the angles
// (th, ph) = (θ, φ) in radians, written once and compiled twice: as C++ by
// common/core/torus.cpp (ts::torusFrame, vec3 = glm::dvec3) and as GLSL by
// the bump-mapping shaders (demos/bump_mapping/bump_mapping_gl.hpp: frameAt), which
// get these lines as the string ts::kTorusFrameGLSL (common/cmake/
// embed_text.cmake copies them at build time, these leading // lines left
// out).  So they may use only what both languages read alike: vec3(...),
// sin, cos, + - *, and the names the including code has set up:
//   in:  th, ph, R, r, TAU (= 2π: d/ds = TAU d/dθ since θ = TAU s)
//   out: N, Q, Qs, Qt, Ns, Nt; declared here: dTh, dPh.
// What each line says is written out in common/core/torus.hpp.
  vec3 dTh = vec3(cos(th), 0.0, -sin(th)), dPh = vec3(-sin(ph) * sin(th), cos(ph), -sin(ph) * cos(th));
  N = vec3(cos(ph) * sin(th), sin(ph), cos(ph) * cos(th));
  Q = vec3((R + r * cos(ph)) * sin(th), r * sin(ph), (R + r * cos(ph)) * cos(th));
  Qs = TAU * (R + r * cos(ph)) * dTh;
  Qt = TAU * r * dPh;
  Ns = TAU * cos(ph) * dTh;
  Nt = TAU * dPh;
