#!/usr/bin/env python3
"""Writes tests/corpus/bad/NNN-short-description.toml: malformed case files, each the coarse smoke case
(tests/smoke/coarse_case.toml) with one edit, or a small file. The first line of each names the field its
error message must name (`# expect: FIELD`); tests/unit/case_corpus_test.cpp reads them all.
Run from the repository root: python3 tests/corpus/make_bad_cases.py (it rewrites the folder)."""
import pathlib
import re
import shutil

ROOT = pathlib.Path(__file__).resolve().parents[2]
BASE = (ROOT / "tests/smoke/coarse_case.toml").read_text()
OUT = ROOT / "tests/corpus/bad"

# (description, expected field, [(from, to), ...]); each `from` must occur exactly once in the base case.
EDITS = [
    # TOML syntax
    ("syntax-double-equals", "TOML syntax error", [("pressure = 0.2", "pressure = = 0.2")]),
    ("syntax-unclosed-array", "TOML syntax error", [("[68.00, 185.00],\n]", "[68.00, 185.00],\n")]),
    ("syntax-unclosed-string", "TOML syntax error", [('title = "175/70R13, inflation 0.2 MPa"', 'title = "175/70R13')]),
    ("syntax-duplicate-key", "TOML syntax error", [("pressure = 0.2", "pressure = 0.2\npressure = 0.3")]),
    ("syntax-duplicate-table", "TOML syntax error", [("[inflation]", "[mesh]\n[inflation]")]),
    # wrong types
    ("type-pressure-string", "inflation.pressure", [("pressure = 0.2", 'pressure = "0.2 MPa"')]),
    ("type-elements-float", "mesh.circumferential_elements", [("circumferential_elements = 36", "circumferential_elements = 36.5")]),
    ("type-half-model-int", "mesh.half_model", [("half_model = true", "half_model = 1")]),
    ("type-profile-point-single", "tyre.profile.points[24]", [("[82.47, 226.81]", "[82.47]")]),
    ("type-profile-point-string", "tyre.profile.points[3]", [("[14.69, 271.64]", '[14.69, "271.64"]')]),
    ("type-interlayer-string", "tyre.interlayer.thickness", [("[tyre.interlayer.thickness]\ns     = [0.0, 55.0, 70.0, 82.0, 95.0, 125.0, 140.0, 153.9]\nvalue = [3.0,  3.0,  6.0,  5.0,  3.5,   3.5,   8.0,   8.0]",
                                                               "[tyre.interlayer]\nthickness = \"3 mm\"")]),
    ("type-support-string", "load_curve[1].support", [('support = { kind = "drum", diameter = 1830.0 }   # drum', 'support = "drum"   # drum')]),
    ("type-load-points-float", "load_curve[0].points", [("max_deflection = 40.0\npoints = 4\n\n[[load_curve]]\nname = \"drum\"",
                                                          "max_deflection = 40.0\npoints = 4.5\n\n[[load_curve]]\nname = \"drum\"")]),
    ("type-slip-string", "rolling[0].states[2].slip", [('{ state = "full_stick", slip = 0.02 }', '{ state = "full_stick", slip = "2%" }')]),
    ("type-cord-modulus-bool", "tyre.plies.carcass.cord_modulus", [("cord_modulus = 3500.0", "cord_modulus = true")]),
    # unknown keys and names
    ("unknown-key-zone", "tyre.zones[2].core_shear_modolus", [("core_shear_modulus = 0.8", "core_shear_modolus = 0.8")]),
    ("unknown-key-root", "titel", [("title =", "titel =")]),
    ("unknown-key-mesh", "mesh.elements", [("[mesh]", "[mesh]\nelements = 3")]),
    ("unknown-key-drum", "load_curve[1].support.diamter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum", diamter = 1830.0 }   # drum')]),
    ("unknown-ply-name", "tyre.zones[0].outer.plies[1]", [('plies = ["belt1", "belt2"], bending', 'plies = ["belt1", "belt3"], bending')]),
    ("unknown-support-kind", "load_curve[1].support.kind", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "cylinder", diameter = 1830.0 }   # drum')]),
    ("unknown-state", "rolling[0].states[0].state", [('{ state = "free" },\n  { state = "full_slip"', '{ state = "freewheel" },\n  { state = "full_slip"')]),
    # missing required keys
    ("missing-core-shear", "tyre.zones[2].core_shear_modulus", [("core_shear_modulus = 0.8\n", "")]),
    ("missing-cord-area", "tyre.plies.carcass.cord_area", [("cord_area = 0.33\n", "")]),
    ("missing-tread-end", "tyre.tread.end_s", [("end_s = 78.0\n", "")]),
    ("missing-profile", "tyre.profile", []),  # built below
    ("missing-drum-diameter", "load_curve[1].support.diameter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum" }   # drum')]),
    ("missing-study-name", "footprint[0].name", [('name = "footprint_3700N"\n', "")]),
    ("missing-shear-modulus-with-rolling", "tyre.tread.shear_modulus", [("shear_modulus = 0.9\n", "")]),
    ("missing-given-radius", "rolling[1].states[1].rolling_radius", [('{ state = "given_slip", slip = 0.02, name = "traction" },\n]',
                                                                       '{ state = "given_radius", name = "traction" },\n]')]),
    # profile
    # the bead end curls back (turning less than 90° at each point) across the lower sidewall
    ("profile-self-intersecting", "tyre.profile.points", [("[70.77, 188.57], [68.00, 185.00],",
                                                            "[70.77, 188.57], [66, 186], [60, 190], [58, 196], [62, 202], [80, 199.2],")]),
    ("profile-inside-out", "tyre.profile.points", []),  # built below
    ("profile-repeated-point", "tyre.profile.points[4]", [("[14.69, 271.64], [19.58, 271.36]", "[14.69, 271.64], [14.69, 271.64]")]),
    ("profile-revisits-point", "tyre.profile.points", [("[70.77, 188.57], [68.00, 185.00],",
                                                         "[70.77, 188.57], [66, 186], [60, 190], [58, 196], [62, 202], [77.43, 200.36],")]),
    ("profile-turns-back", "tyre.profile.points[4]", [("[14.69, 271.64], [19.58, 271.36]", "[19.58, 271.36], [14.69, 271.64]")]),
    ("profile-negative-x", "tyre.profile.points[1]", [("[ 4.90, 271.96]", "[ -4.90, 271.96]")]),
    ("profile-not-on-equator", "tyre.profile.points[0]", [("[ 0.00, 272.00]", "[ 1.00, 272.00]")]),
    ("profile-nan", "tyre.profile.points[2]", [("[ 9.80, 271.84]", "[ nan, 271.84]")]),
    ("profile-empty", "tyre.profile.points", []),  # built below
    ("profile-spline-crosses", "tyre.profile.points[8]", []),  # built below
    ("profile-spline-crosses-equator", "tyre.profile.points[0]", []),  # built below
    ("profile-touches-equator", "tyre.profile.points[1]", [("[ 4.90, 271.96]", "[ 0.0, 271.9]")]),
    # drums
    ("drum-tiny", "load_curve[1].support.diameter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum", diameter = 0.001 }   # drum')]),
    ("drum-smaller-than-tyre", "load_curve[1].support.diameter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum", diameter = 500.0 }   # drum')]),
    ("drum-huge", "load_curve[1].support.diameter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum", diameter = 1e300 }   # drum')]),
    ("drum-rolling-small", "rolling[1].support.diameter", [('name = "rolling_drum"\nsupport = { kind = "drum", diameter = 1830.0 }',
                                                            'name = "rolling_drum"\nsupport = { kind = "drum", diameter = 1.0 }')]),
    ("drum-inf", "load_curve[1].support.diameter", [('{ kind = "drum", diameter = 1830.0 }   # drum', '{ kind = "drum", diameter = inf }   # drum')]),
    # sizes
    ("mesh-1e7-circumferential", "mesh.circumferential_elements", [("circumferential_elements = 36", "circumferential_elements = 10000000")]),
    ("mesh-1e9-meridional", "mesh.meridional_elements", [("meridional_elements = 10", "meridional_elements = 1000000000")]),
    ("mesh-beyond-cap", "mesh.circumferential_elements", [("circumferential_elements = 36", "circumferential_elements = 20000")]),
    ("mesh-rolling-huge", "rolling[0].mesh.circumferential_elements", [("mesh = { circumferential_elements = 40, meridional_elements = 12 }\nstates = [\n  { state = \"free\" },\n  { state = \"full_slip\"",
                                                                         "mesh = { circumferential_elements = 4000000, meridional_elements = 12 }\nstates = [\n  { state = \"free\" },\n  { state = \"full_slip\"")]),
    ("mesh-zero-meridional", "mesh.meridional_elements", [("meridional_elements = 10", "meridional_elements = 0")]),
    ("mesh-two-circumferential", "mesh.circumferential_elements", [("circumferential_elements = 36", "circumferential_elements = 2")]),
    ("mesh-refinement-nan", "mesh.circumferential_refinement", [("circumferential_refinement = 4.0", "circumferential_refinement = nan")]),
    ("mesh-int-overflow", "mesh.circumferential_elements", [("circumferential_elements = 36", "circumferential_elements = 99999999999")]),
    ("load-points-million", "load_curve[0].points", [("max_deflection = 40.0\npoints = 4\n\n[[load_curve]]\nname = \"drum\"",
                                                       "max_deflection = 40.0\npoints = 1000000\n\n[[load_curve]]\nname = \"drum\"")]),
    ("load-points-zero", "load_curve[0].points", [("max_deflection = 40.0\npoints = 4\n\n[[load_curve]]\nname = \"drum\"",
                                                    "max_deflection = 40.0\npoints = 0\n\n[[load_curve]]\nname = \"drum\"")]),
    ("sweep-points-huge", "rolling[0].sweep.points", [("to = 0.15, points = 3, hold", "to = 0.15, points = 5000, hold")]),
    ("deflection-beyond-rim", "load_curve[0].max_deflection", [("max_deflection = 40.0\npoints = 4\n\n[[load_curve]]\nname = \"drum\"",
                                                                 "max_deflection = 395.0\npoints = 4\n\n[[load_curve]]\nname = \"drum\"")]),
    ("deflection-negative", "load_curve[2].max_deflection", [("max_deflection = 40.0\npoints = 4\n\n# Footprint", "max_deflection = -40.0\npoints = 4\n\n# Footprint")]),
    # names
    ("state-name-dotdot", "rolling[0].states[3].name", [('name = "traction" },\n  { state = "given_slip", slip = -0.02', 'name = ".." },\n  { state = "given_slip", slip = -0.02')]),
    ("state-name-dot", "rolling[1].states[0].name", [('states = [\n  { state = "free" },\n  { state = "given_slip", slip = 0.02, name = "traction" },\n]',
                                                      'states = [\n  { state = "free", name = "." },\n  { state = "given_slip", slip = 0.02, name = "traction" },\n]')]),
    ("state-name-hidden", "rolling[0].states[0].name", [('{ state = "free" },\n  { state = "full_slip"', '{ state = "free", name = ".hidden" },\n  { state = "full_slip"')]),
    ("state-name-slash", "rolling[0].states[0].name", [('{ state = "free" },\n  { state = "full_slip"', '{ state = "free", name = "a/b" },\n  { state = "full_slip"')]),
    ("state-name-long", "rolling[0].states[0].name", [('{ state = "free" },\n  { state = "full_slip"', '{ state = "free", name = "' + "x" * 120 + '" },\n  { state = "full_slip"')]),
    ("study-name-dotdot", "footprint[0].name", [('name = "footprint_3700N"', 'name = ".."')]),
    ("study-name-slash", "load_curve[0].name", [('name = "plane"\nsupport = { kind = "plane" }\ntheory = "nonlinear"', 'name = "../plane"\nsupport = { kind = "plane" }\ntheory = "nonlinear"')]),
    ("study-name-duplicate", "load_curve[2].name", [('name = "plane_linear"', 'name = "plane"')]),
    ("study-name-empty", "rolling[1].name", [('name = "rolling_drum"', 'name = ""')]),
    # rolling radius and slip
    ("radius-1e9", "rolling[1].states[1].rolling_radius", [('{ state = "given_slip", slip = 0.02, name = "traction" },\n]',
                                                            '{ state = "given_radius", rolling_radius = 1e9, name = "traction" },\n]')]),
    ("radius-tiny", "rolling[1].states[1].rolling_radius", [('{ state = "given_slip", slip = 0.02, name = "traction" },\n]',
                                                             '{ state = "given_radius", rolling_radius = 1.0, name = "traction" },\n]')]),
    ("radius-negative", "rolling[1].states[1].rolling_radius", [('{ state = "given_slip", slip = 0.02, name = "traction" },\n]',
                                                                 '{ state = "given_radius", rolling_radius = -280.0, name = "traction" },\n]')]),
    ("slip-locked", "rolling[0].states[3].slip", [('slip = 0.02, name = "traction" },\n  { state = "given_slip", slip = -0.02', 'slip = -1.0, name = "traction" },\n  { state = "given_slip", slip = -0.02')]),
    ("slip-inf", "rolling[0].states[4].slip", [('slip = -0.02, name = "braking"', 'slip = -inf, name = "braking"')]),
    ("friction-zero", "rolling[0].friction", [('name = "rolling_plane"\nsupport = { kind = "plane" }\nfriction = 0.7', 'name = "rolling_plane"\nsupport = { kind = "plane" }\nfriction = 0.0')]),
    # plausibility bounds
    ("cord-modulus-1e30", "tyre.plies.carcass.cord_modulus", [("cord_modulus = 3500.0", "cord_modulus = 1e30")]),
    ("cord-modulus-negative", "tyre.plies.belt1.cord_modulus", [("cord_modulus = 160000.0\ncord_area = 0.196\nends_per_mm = 0.8\nangle = 22.0",
                                                                  "cord_modulus = -160000.0\ncord_area = 0.196\nends_per_mm = 0.8\nangle = 22.0")]),
    ("rubber-modulus-tiny", "tyre.plies.carcass.rubber_modulus", [("rubber_modulus = 4.0", "rubber_modulus = 1e-9")]),
    ("rubber-layer-E-huge", "tyre.zones[1].outer.rubber.E", [("E = 4.0", "E = 4e9")]),
    ("core-shear-huge", "tyre.zones[0].core_shear_modulus", [("core_shear_modulus = 1.5", "core_shear_modulus = 1.5e12")]),
    ("core-normal-zero", "tyre.zones[3].core_normal_modulus", [("core_shear_modulus = 2.0\ncore_normal_modulus = 100.0", "core_shear_modulus = 2.0\ncore_normal_modulus = 0.0")]),
    ("ply-thickness-huge", "tyre.plies.carcass.thickness", [("thickness = 1.0\nrubber_modulus = 4.0", "thickness = 1e6\nrubber_modulus = 4.0")]),
    ("interlayer-1e6", "tyre.interlayer.thickness.value[0]", [("value = [3.0,  3.0,  6.0,  5.0,  3.5,   3.5,   8.0,   8.0]", "value = [1e6,  3.0,  6.0,  5.0,  3.5,   3.5,   8.0,   8.0]")]),
    ("interlayer-negative", "tyre.interlayer.thickness.value[3]", [("value = [3.0,  3.0,  6.0,  5.0,", "value = [3.0,  3.0,  6.0,  -1,")]),
    ("tread-height-huge", "tyre.tread.height.value[1]", [("value = [10.0, 10.0, 8.0, 8.0]", "value = [10.0, 1e5, 8.0, 8.0]")]),
    ("tread-stiffness-1e9", "tyre.tread.stiffness", [("stiffness = 1.0", "stiffness = 1e9")]),
    ("tread-stiffness-zero", "tyre.tread.stiffness", [("stiffness = 1.0", "stiffness = 0")]),
    ("tread-shear-huge", "tyre.tread.shear_modulus", [("shear_modulus = 0.9", "shear_modulus = 9e9")]),
    ("pressure-huge", "inflation.pressure", [("pressure = 0.2", "pressure = 200.0")]),
    ("pressure-negative", "inflation.pressure", [("pressure = 0.2", "pressure = -0.2")]),
    ("pressure-nan", "inflation.pressure", [("pressure = 0.2", "pressure = nan")]),
    ("stiffness-huge", "tyre.zones[1].outer.stiffness[0][0]", [("outer = { rubber = { E = 4.0, nu = 0.49, thickness = 4.0 } }",
                                                                "outer = { stiffness = [[1e12, 0, 0], [0, 1e12, 0], [0, 0, 1e12]] }")]),
    # other values
    ("zones-empty", "tyre.zones", []),  # built below
    ("zone-end-short", "tyre.zones[3].s_end", [("s_end = 153.9", "s_end = 150.0")]),
    ("ply-angle", "tyre.plies.carcass.angle", [("angle = 90.0", "angle = 95.0")]),
    ("quadrature-zero", "contact.quadrature", [("quadrature = 4", "quadrature = 0")]),
    ("target-load-negative", "footprint[0].target_load", [("target_load = 3700.0", "target_load = -3700.0")]),
    ("target-load-huge", "footprint[0].target_load", [("target_load = 3700.0", "target_load = 1e300")]),
    ("contact-iterations-huge", "contact.max_contact_iterations", [("max_contact_iterations = 30", "max_contact_iterations = 1000000000")]),
    ("load-tolerance-inf", "footprint[0].load_tolerance", [("load_tolerance = 1e-3", "load_tolerance = inf")]),
    ("surface-empty-terms", "load_curve[0].support.terms", [('name = "plane"\nsupport = { kind = "plane" }\ntheory = "nonlinear"',
                                                              'name = "plane"\nsupport = { kind = "surface", terms = [] }\ntheory = "nonlinear"')]),
    ("rolling-no-states", "rolling[1]", [('states = [\n  { state = "free" },\n  { state = "given_slip", slip = 0.02, name = "traction" },\n]', "states = []")]),
    # modelling options (issue 10 item 5)
    ("footprint-load-and-deflection", "footprint[0].deflection", [("target_load = 3700.0", "target_load = 3700.0\ndeflection = 20.0")]),
    ("footprint-deflection-negative", "footprint[0].deflection", [("target_load = 3700.0", "deflection = -5.0")]),
    ("footprint-deflection-beyond-bead", "footprint[0].deflection", [("target_load = 3700.0", "deflection = 500.0")]),
    ("deflection-from-unknown", "load_curve[0].deflection_from", [('name = "plane"\nsupport = { kind = "plane" }\ntheory = "nonlinear"',
                                                                  'name = "plane"\nsupport = { kind = "plane" }\ntheory = "nonlinear"\ndeflection_from = "inflated"')]),
    ("meridional-grading-unknown", "mesh.meridional_grading", [("half_model = true", 'half_model = true\nmeridional_grading = "uniform"')]),
    ("face-bending-negative", "tyre.zones[0].outer.bending_stiffness[1]",
     [("bending_stiffness = [100.0, 300.0]", "bending_stiffness = [100.0, -1000.0]")]),
    ("face-bending-one-number", "tyre.zones[0].outer.bending_stiffness",
     [("bending_stiffness = [100.0, 300.0]", "bending_stiffness = [1000.0]")]),
    # the rim flange (a table the smoke case does not have: each edit adds one)
    ("rim-flange-radius-zero", "tyre.rim_flange.radius",
     [("[tyre.tread]\n", "[tyre.rim_flange]\nradius = 0.0\nstiffness = 20.0\n\n[tyre.tread]\n")]),
    ("rim-flange-missing-stiffness", "tyre.rim_flange.stiffness",
     [("[tyre.tread]\n", "[tyre.rim_flange]\nradius = 9.5\n\n[tyre.tread]\n")]),
    ("rim-flange-stiffness-huge", "tyre.rim_flange.stiffness",
     [("[tyre.tread]\n", "[tyre.rim_flange]\nradius = 9.5\nstiffness = 1e9\n\n[tyre.tread]\n")]),
    ("rim-flange-unknown-key", "tyre.rim_flange.radus",
     [("[tyre.tread]\n", "[tyre.rim_flange]\nradus = 9.5\nstiffness = 20.0\n\n[tyre.tread]\n")]),
    ("face-in-plane-bending-negative", "tyre.zones[0].outer.in_plane_bending_stiffness[0]",
     [("bending_stiffness = [100.0, 300.0]", "bending_stiffness = [100.0, 300.0], in_plane_bending_stiffness = [-5.0, 0.0]")]),
    ("face-in-plane-bending-three-numbers", "tyre.zones[0].outer.in_plane_bending_stiffness",
     [("bending_stiffness = [100.0, 300.0]", "bending_stiffness = [100.0, 300.0], in_plane_bending_stiffness = [5.0, 0.0, 1.0]")]),
]


def apply(text, edits, name):
    for old, new in edits:
        count = text.count(old)
        if count != 1:
            raise SystemExit(f"{name}: '{old[:40]}' occurs {count} times")
        text = text.replace(old, new)
    return text


def special(name, text):
    if name == "profile-inside-out":  # the same tyre turned inside out: r mirrored about the bead height
        def flip(m):
            return f"[{m.group(1)}, {2 * 185.0 + 87.0 - float(m.group(2)):.2f}]"
        start = text.index("points = [")
        end = text.index("]\n\n", start)
        body = re.sub(r"\[\s*([-0-9.]+),\s*([-0-9.]+)\]", flip, text[start + 10:end])
        return text[:start + 10] + body + text[end:]
    if name == "profile-empty":
        start = text.index("points = [")
        end = text.index("]\n\n", start)
        return text[:start] + "points = [" + text[end:]
    spline = {"profile-spline-crosses": "[0, 272], [40, 270], [70, 255], [80, 230], [72, 205], [50, 195], [35, 210], "
                                        "[30, 240], [26, 265], [5, 271.55]",
              "profile-spline-crosses-equator": "[0, 272], [0.2, 250], [40, 245], [60, 200]"}
    if name in spline:  # the points do not cross, the spline through them does
        start = text.index("points = [")
        end = text.index("]\n\n", start)
        return text[:start] + "points = [" + spline[name] + "]" + text[end + 1:]
    if name == "missing-profile":
        start = text.index("[tyre.profile]")
        end = text.index("]\n\n", start)
        return text[:start] + text[end + 3:]
    if name == "zones-empty":
        return "title = \"no zones\"\n[tyre]\nzones = []\n[tyre.profile]\npoints = [[0, 280], [60, 260], [70, 190]]\n" \
               "[tyre.interlayer]\nthickness = 3.0\n[tyre.tread]\nheight = 8.0\nend_s = 60.0\nstiffness = 1.0\n"
    return text


def main():
    # Every file is made before the folder is touched: a stale edit stops the script with the old corpus intact.
    files = {}
    for k, (name, expect, edits) in enumerate(EDITS, start=1):
        text = special(name, apply(BASE, edits, name))
        if text == BASE:
            raise SystemExit(f"{name}: no change")
        files[f"{k:03d}-{name}.toml"] = f"# expect: {expect}\n" + text
    if OUT.exists():
        shutil.rmtree(OUT)
    OUT.mkdir(parents=True)
    for file_name, text in files.items():
        (OUT / file_name).write_text(text)
    print(f"{len(EDITS)} files in {OUT}")


if __name__ == "__main__":
    main()
