# Lab 07's classic mistakes (handouts/07_particles.md); each must fail its step first, and
# its first failure's why must say the SAYS words (the concept, not a field's name).

labkit_mutant(07 particles NAME births_drop_fraction STEP 1 SAYS "fraction" "carried"
  FIND "return {int(whole), due - whole};"
  REPLACE "return {int(whole), 0.0};")

labkit_mutant(07 particles NAME cone_uniform_in_angle STEP 1 SAYS "solid angle"
  FIND "const double cos_theta = random.uniform(std::cos(emitter.cone), 1.0);"
  REPLACE "const double cos_theta = std::cos(random.uniform(0.0, emitter.cone));")

labkit_mutant(07 particles NAME semi_implicit_euler STEP 2 SAYS "explicit Euler" "start of the step"
  FIND "next.position = p.position + p.velocity * dt;"
  REPLACE "next.position = p.position + (p.velocity + a * dt) * dt;")

labkit_mutant(07 particles NAME verlet_start_without_acceleration STEP 2 SAYS "Taylor step"
  FIND "next.previous = p.position - p.velocity * dt + 0.5 * a * dt * dt;"
  REPLACE "next.previous = p.position - p.velocity * dt;")

# Step 2: the air drag taken per component, -k2 |v_i| v_i, instead of -k2 |v| v along the
# whole velocity: right for motion along one axis only.
labkit_mutant(07 particles NAME drag_per_component STEP 2 SAYS "whole velocity vector"
  FIND "- forces.air_drag * p.velocity.norm() * p.velocity;"
  REPLACE "- forces.air_drag * p.velocity.cwiseAbs().cwiseProduct(p.velocity);")

labkit_mutant(07 particles NAME launch_height_sign STEP 3 SAYS "height" "gravity points down"
  FIND "const double D = v2 * v2 + 2 * v2 * d.dot(gravity) - gx_squared;"
  REPLACE "const double D = v2 * v2 - 2 * v2 * d.dot(gravity) - gx_squared;")

# The issue's: v^2 - sqrt(D) for the low root loses every digit on a near, fast shot.
labkit_mutant(07 particles NAME low_root_cancels STEP 3 SAYS "low root" "cancels"
  FIND "const double tan_low = (g * x * x + 2 * y * v2) / (x * (v2 + root));"
  REPLACE "const double tan_low = (v2 - root) / (g * x);")

labkit_mutant(07 particles NAME plane_two_sided STEP 4 SAYS "one-sided"
  FIND "if (va < 0) return {};"
  REPLACE "if (va < 0 && vb >= 0) { SurfaceHit h; h.hit = true; h.t = va / (va - vb); h.point = segment.point(h.t); h.normal = -plane.normal / length; return h; }\n  if (va < 0) return {};")

labkit_mutant(07 particles NAME touching_is_behind STEP 4 SAYS "not behind"
  FIND "if (vb >= 0) return {};"
  REPLACE "if (vb > 0) return {};")

# Step 4's rule for a: on the plane to within value(a)'s rounding bound counts as on it.
labkit_mutant(07 particles NAME start_decided_by_rounded_sign STEP 4 SAYS "rounding bound"
  FIND "const double va = std::abs(a.value) <= a.error ? 0.0 : a.value, vb"
  REPLACE "const double va = a.value, vb")

labkit_mutant(07 particles NAME friction_reverses_sliding STEP 5 SAYS "never reverses"
  FIND "const double f = std::min(material.friction * j, mass * slide);"
  REPLACE "const double f = material.friction * j;")

labkit_mutant(07 particles NAME impulse_ignores_object_velocity STEP 5 SAYS "relative velocity"
  FIND "const Vec3 relative = velocity - object_velocity;"
  REPLACE "const Vec3 relative = velocity;")

labkit_mutant(07 particles NAME whole_step_after_bounce STEP 6 SAYS "remaining time"
  FIND "remaining *= 1 - hit.t;"
  REPLACE "")

# A moving scene (step 6): the three ways to leave its motion out.
labkit_mutant(07 particles NAME collide_impulse_absolute_velocity STEP 6 SAYS "relative velocity" "v - u"
  FIND "v = impulse(v, u, hit.normal, mass, scene.material).velocity;"
  REPLACE "v = impulse(v, Vec3::Zero(), hit.normal, mass, scene.material).velocity;")

labkit_mutant(07 particles NAME moving_surface_frozen STEP 6 SAYS "relative step" "a + u dt"
  FIND "Segment piece = {step.a + u * dt, step.b};"
  REPLACE "Segment piece = step;")

labkit_mutant(07 particles NAME piece_moves_with_world_velocity STEP 6 SAYS "relative to the moving surfaces"
  FIND "piece = {bounce.from, bounce.from + (v - u) * remaining};"
  REPLACE "piece = {bounce.from, bounce.from + v * remaining};")

labkit_mutant(07 particles NAME cap_off_by_one STEP 6 SAYS "bounce cap"
  FIND "if (c.bounces == cap) {"
  REPLACE "if (c.bounces == cap + 1 || c.bounces == kMaxBounceCap) {")

labkit_mutant(07 particles NAME hit_point_not_settled STEP 7 SAYS "strictly in front" "settle"
  FIND "bounce.from = settle_in(hit.point, scene, hit);"
  REPLACE "bounce.from = hit.point;")

labkit_mutant(07 particles NAME verlet_previous_kept STEP 8 SAYS "previous" "Verlet"
  FIND "if (integrator == Integrator::verlet && (c.bounces > 0 || c.stopped)) p.previous = p.position - p.velocity * dt;"
  REPLACE "")

# Step 7: collide's end position left as computed, not settled: after a bounce that
# slides along a surface it can end a hair behind the plane, by rounding.
labkit_mutant(07 particles NAME end_position_not_settled STEP 7 SAYS "behind"
  FIND "c.position = settle_in(piece.b, scene, last);"
  REPLACE "c.position = piece.b;")

# Step 7: the plane just hit taken as "not behind" is enough: a point exactly on it
# (value 0) is left there, and the next piece starts on the surface instead of off it.
labkit_mutant(07 particles NAME hit_plane_not_strict STEP 7 SAYS "strictly in front"
  FIND "const bool strict = last.hit && last.plane == int(i);"
  REPLACE "const bool strict = false;")

# Step 8: settle keeps x off the surface just hit and nothing else: in a crease the push
# off that surface leaves x behind the other one.
labkit_mutant(07 particles NAME settles_off_last_only STEP 8 SAYS "crease" "behind"
  FIND "keep[i] =\n        scene.planes[i].normal != Vec3::Zero() && (s.value >= -1000 * s.error || (last.hit && last.plane == int(i)));"
  REPLACE "keep[i] = last.hit && last.plane == int(i);")


# Step 9 (extension): the damper on the whole relative velocity brakes particles that
# circle each other at a fixed length; a spring damps only the change of its length.
labkit_mutant(07 particles NAME spring_damps_whole_relative_velocity STEP 9 SAYS "along the spring"
  FIND "return -(spring.stiffness * stretch + spring.damping * lengthening) * u;"
  REPLACE "return -spring.stiffness * stretch * u - spring.damping * (a.velocity - b.velocity);")

# Step 9: d = b - a gives the force on b (or the sign flipped): the spring pushes when
# stretched.
labkit_mutant(07 particles NAME spring_force_on_b STEP 9 SAYS "force is on a"
  FIND "const Vec3 d = a.position - b.position;"
  REPLACE "const Vec3 d = b.position - a.position;")

# Step 9: Hooke's law on the whole length: a spring that is never at rest.
labkit_mutant(07 particles NAME spring_ignores_rest_length STEP 9 SAYS "rest length"
  FIND "const double stretch = l - spring.rest_length;"
  REPLACE "const double stretch = l;")

# Step 10 (extension): the particle formula j = -(1 + e) v_rel / (1/m_a + 1/m_b): the
# bodies' turning left out of j, so the contact points do not separate at -e v_rel.
labkit_mutant(07 particles NAME rigid_angular_part_forgotten STEP 10 SAYS "angular terms" "denominator"
  FIND "const double denominator = 1 / a.mass + 1 / b.mass + n.dot(turn_a.cross(r_a)) + n.dot(turn_b.cross(r_b));"
  REPLACE "const double denominator = 1 / a.mass + 1 / b.mass;")

# Step 10: J x r instead of r x J: the torque impulse turns the body the wrong way.
labkit_mutant(07 particles NAME rigid_torque_order_swapped STEP 10 SAYS "r_a x J"
  FIND "out.angular_velocity_a = a.angular_velocity + a.inverse_inertia * r_a.cross(J);"
  REPLACE "out.angular_velocity_a = a.angular_velocity + a.inverse_inertia * J.cross(r_a);")

# Step 10: the angular momentum change r x J taken as the angular velocity change: the
# inverse inertia not applied.
labkit_mutant(07 particles NAME rigid_inverse_inertia_not_applied STEP 10 SAYS "inverse inertia"
  FIND "out.angular_velocity_b = b.angular_velocity - b.inverse_inertia * r_b.cross(J);"
  REPLACE "out.angular_velocity_b = b.angular_velocity - r_b.cross(J);")
