// The bunny scene of apps/bunny/scene.cpp (rtlab-bunny, default material "diffuse") for POV-Ray 3.7, for the
// race in scripts/peer-povray.sh. The mesh comes from bunny_mesh.inc, written by scripts/peer/mesh_to_pov.py
// from the same model file (placed, scaled and smooth-shaded as the app does); put its folder on the library
// path (+L). Right-handed world (`right -x`), linear colours (assumed_gamma 1), classic convention.
#version 3.7;

#include "bunny_mesh.inc"  // PeerMesh, PeerMeshTop

global_settings {
  assumed_gamma 1.0
  ambient_light 1
  max_trace_level 9  // rtlab's max_depth 8 plus the camera ray
  adc_bailout 0.001
}

#declare Aspect = image_width / image_height;
#declare VerticalFov = 40;
camera {
  perspective
  location <0, 0.55 * PeerMeshTop + 0.9, 4.2>
  right -x * Aspect
  up y
  angle 2 * degrees(atan(Aspect * tan(radians(VerticalFov / 2))))
  look_at <0, 0.45 * PeerMeshTop, 0>
}

light_source { <-3, 6, 4> color rgb 0.9 }
background { color rgb <0.55, 0.65, 0.8> }

// rtlab's "lambert" albedo <0.8, 0.75, 0.68> under ambient 0.15.
object {
  PeerMesh
  texture {
    pigment { color rgb <0.8, 0.75, 0.68> }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0 }
  }
}

// The floor: 12 x 12 unit tiles on y = 0; rtlab's tile (floor(x + 6), floor(6 - z)) shows 0.75 when even.
// The checker is moved half a unit in y as in whitted.pov; with it, 0.75 is POV-Ray's second colour.
polygon {
  5, <-6, 0, 6>, <6, 0, 6>, <6, 0, -6>, <-6, 0, -6>, <-6, 0, 6>
  texture {
    pigment { checker color rgb 0.35 color rgb 0.75 translate -0.5 * y }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0 }
  }
}
