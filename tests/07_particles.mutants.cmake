# Lab 07's classic mistakes (handouts/07_particles.md); each must fail its step.

labkit_mutant(07 particles NAME births_drop_fraction STEP 1
  FIND "return {int(whole), due - whole};"
  REPLACE "return {int(whole), 0.0};")

labkit_mutant(07 particles NAME cone_uniform_in_angle STEP 1
  FIND "const double cos_theta = random.uniform(std::cos(emitter.cone), 1.0);"
  REPLACE "const double cos_theta = std::cos(random.uniform(0.0, emitter.cone));")

labkit_mutant(07 particles NAME semi_implicit_euler STEP 2
  FIND "next.position = p.position + p.velocity * dt;"
  REPLACE "next.position = p.position + (p.velocity + a * dt) * dt;")

labkit_mutant(07 particles NAME verlet_start_without_acceleration STEP 2
  FIND "next.previous = p.position - p.velocity * dt + 0.5 * a * dt * dt;"
  REPLACE "next.previous = p.position - p.velocity * dt;")

labkit_mutant(07 particles NAME launch_height_sign STEP 3
  FIND "const double D = v2 * v2 + 2 * v2 * d.dot(gravity) - gx_squared;"
  REPLACE "const double D = v2 * v2 - 2 * v2 * d.dot(gravity) - gx_squared;")

labkit_mutant(07 particles NAME plane_two_sided STEP 4
  FIND "if (va < 0) return {};   // starts behind: not this step's doing"
  REPLACE "if (va < 0 && vb >= 0) { SurfaceHit h; h.hit = true; h.t = va / (va - vb); h.point = segment.point(h.t); h.normal = -plane.normal / length; return h; }
  if (va < 0) return {};")

labkit_mutant(07 particles NAME touching_is_behind STEP 4
  FIND "if (vb >= 0) return {};  // does not end behind (touching the plane is allowed)"
  REPLACE "if (vb > 0) return {};")

labkit_mutant(07 particles NAME friction_reverses_sliding STEP 5
  FIND "const double f = std::min(material.friction * j, mass * slide);  // never reverses v_t"
  REPLACE "const double f = material.friction * j;")

labkit_mutant(07 particles NAME impulse_ignores_object_velocity STEP 5
  FIND "const Vec3 relative = velocity - object_velocity;"
  REPLACE "const Vec3 relative = velocity;")

labkit_mutant(07 particles NAME whole_step_after_bounce STEP 6
  FIND "remaining *= 1 - hit.t;"
  REPLACE "")

labkit_mutant(07 particles NAME cap_off_by_one STEP 6
  FIND "if (c.bounces == cap) {  // one hit too many: stop here, at rest"
  REPLACE "if (c.bounces == cap + 1 || c.bounces == kMaxBounceCap) {")

labkit_mutant(07 particles NAME hit_point_not_settled STEP 7
  FIND "bounce.from = settle(hit.point, scene, hit);"
  REPLACE "bounce.from = hit.point;")

labkit_mutant(07 particles NAME verlet_previous_kept STEP 7
  FIND "if (integrator == Integrator::verlet && (c.bounces > 0 || c.stopped)) p.previous = p.position - p.velocity * dt;"
  REPLACE "")
