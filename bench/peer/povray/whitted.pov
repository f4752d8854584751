// The 1980 Whitted scene of apps/whitted/scene.cpp (rtlab-whitted) for POV-Ray 3.7, for the race in
// scripts/peer-povray.sh. Right-handed world as rtlab's (hence `right -x`), linear colours (assumed_gamma 1;
// render with File_Gamma=sRGB as rtlab writes its PNG), the classic convention: no light fall-off,
// diffuse kd (n.l), Phong highlight ks (r.v)^e, ambient kd * 0.12.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light 1
  // rtlab stops after 8 reflections or refractions (max_depth 8); POV-Ray counts the camera ray as level 1.
  max_trace_level 9
  // rtlab's min_weight: a secondary ray carrying less than 1e-3 is not traced.
  adc_bailout 0.001
}

// rtlab's CameraSpec gives the vertical field of view; POV-Ray's `angle` is the horizontal one.
#declare Aspect = image_width / image_height;
#declare VerticalFov = 45;
camera {
  perspective
  location <0, 2, 4>
  right -x * Aspect
  up y
  angle 2 * degrees(atan(Aspect * tan(radians(VerticalFov / 2))))
  look_at <0, 0.9, -2.5>
}

light_source { <-4, 9, 6> color rgb 0.9 }  // no fade: the classic convention's point light
background { color rgb <0.25, 0.5, 0.95> }

// The board: 8 x 14 unit tiles on y = 0, x in [-4, 4], z in [-12, 2]; rtlab's tile (floor(x + 4),
// floor(2 - z)) is red when its parity is even. POV-Ray's checker is 3D: it is moved half a unit so that
// floor(y) is the same on the whole board (hits at y = +-1e-9 would otherwise flip tiles), and its colour
// order was checked against rtlab's picture: yellow first.
polygon {
  5, <-4, 0, 2>, <4, 0, 2>, <4, 0, -12>, <-4, 0, -12>, <-4, 0, 2>
  texture {
    pigment { checker color rgb <0.95, 0.85, 0.1> color rgb <0.8, 0.04, 0.02> translate -0.5 * y }
    finish { ambient 0.12 diffuse 1 specular 0 phong 0 }
  }
}

// The mirror sphere: rtlab's phong with kd 0.05, ks 0.6, exponent 80, kr 0.8 (no Fresnel).
sphere {
  <1.25, 1, -4.3>, 1
  texture {
    pigment { color rgb 0.05 }
    finish { ambient 0.12 diffuse 1 phong 0.6 phong_size 80 reflection { 0.8 } }
  }
}

// The hollow glass sphere: a shell of index 1.5 around air. rtlab builds it from two spheres (the inner one
// with index 1 inside and 1.5 outside); in POV-Ray it is the CSG difference, whose interior is the shell.
// Glass has no direct light or ambient of its own; Fresnel splits reflection from transmission
// (conserve_energy takes the reflected share from the transmitted one); shadows pass through it whole.
difference {
  sphere { <-0.75, 1.3, -1.4>, 0.85 }
  sphere { <-0.75, 1.3, -1.4>, 0.75 }
  texture {
    pigment { color rgbt <1, 1, 1, 1> }
    finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}
