#!/usr/bin/env python3
"""The formats' own tools accept what `dtoadq convert` writes (docs/interchange.md, "Checked by the
formats' own tools").

- MaterialX: every bundled openpbr preset written as .mtlx is read with MaterialX's own reader
  (readFromXmlFile), MaterialX's standard libraries imported (open_pbr_surface's nodedef among
  them), and Document.validate() must pass; its shader node must resolve to its nodedef.
- glTF: every bundled openpbr preset written as .gltf must validate against the glTF 2.0 JSON
  schema (glTF.schema.json) and each material extension against its own schema, committed in
  interchange/schema/gltf/ with their licence; every extension a material uses must be listed in
  extensionsUsed and every listed one used.

And the other way: documents MaterialX's own writer makes (an open_pbr_surface and a
standard_surface material) are read by `dtoadq convert` into the values set, or the translation
graph's for standard_surface.

Before it checks the lab's files, it checks that each validator refuses broken variants (an input
of the wrong type, an unknown input, a dangling shader reference; a roughness of 2, no asset, a
negative clearcoat, an extension missing from extensionsUsed), so it can fail.

Needs the Python packages `materialx` and `jsonschema`, which `sh tools/install-deps.sh --tests`
installs into the virtual environment .venv/ of the repository; run by another Python, the script
re-runs itself with .venv/bin/python3, and exits 77 (ctest: skipped) saying so when there is none.
"""
import copy
import glob
import importlib.metadata
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SKIPPED = 77

try:
    import MaterialX as mx
    import jsonschema
    import referencing
except ImportError:
    venv = os.path.join(ROOT, ".venv")
    venv_python = os.path.join(venv, "bin", "python3")
    if os.path.exists(venv_python) and os.path.realpath(sys.prefix) != os.path.realpath(venv):
        os.execv(venv_python, [venv_python] + sys.argv)
    print("check_interchange_validity: skipped: no Python with the materialx and jsonschema packages "
          "(sh tools/install-deps.sh --tests makes .venv/ with them)")
    sys.exit(SKIPPED)

SCHEMAS = os.path.join(ROOT, "interchange", "schema", "gltf")


def mtlx_problems(path, library):
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, path)
    doc.importLibrary(library)
    ok, message = doc.validate()
    problems = [] if ok else [message.strip()]
    for material in doc.getMaterialNodes():
        for shader in mx.getShaderNodes(material):
            if shader.getNodeDef() is None:
                problems.append(f"{shader.getName()}: no nodedef of the standard libraries matches")
    if not doc.getMaterialNodes():
        problems.append("no material node")
    return problems


def gltf_validators():
    resources = []
    for path in glob.glob(os.path.join(SCHEMAS, "*.schema.json")):
        with open(path) as f:
            schema = json.load(f)
        resources.append((os.path.basename(path), referencing.Resource.from_contents(
            schema, default_specification=referencing.jsonschema.DRAFT4)))
    registry = referencing.Registry().with_resources(resources)

    def validator(name):
        schema = registry.contents(name)
        return jsonschema.validators.validator_for(schema, default=jsonschema.Draft4Validator)(schema, registry=registry)
    return validator


def gltf_problems(doc, validator):
    problems = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator("glTF.schema.json").iter_errors(doc)]
    used = set()
    for k, material in enumerate(doc.get("materials", [])):
        for name, extension in material.get("extensions", {}).items():
            used.add(name)
            schema = f"material.{name}.schema.json"
            if not os.path.exists(os.path.join(SCHEMAS, schema)):
                problems.append(f"materials/{k}/extensions/{name}: no schema committed for it")
                continue
            problems += [f"materials/{k}/extensions/{name}/{'/'.join(map(str, e.absolute_path))}: {e.message}"
                         for e in validator(schema).iter_errors(extension)]
    listed = set(doc.get("extensionsUsed", []))
    problems += [f"extension {name} is used but not in extensionsUsed" for name in sorted(used - listed)]
    problems += [f"extension {name} is in extensionsUsed but not used" for name in sorted(listed - used)]
    return problems


def materialx_written_documents_read_back(dtoadq, folder):
    """Documents MaterialX's own writer makes (writeToXmlFile): an open_pbr_surface and a
    standard_surface material, read by `dtoadq convert` into presets whose values are those set
    (open_pbr_surface) or the translation graph's (standard_surface). The values are exact in binary,
    so the comparison is exact."""
    failures = []
    cases = {
        "open_pbr_surface": ({"base_color": mx.Color3(0.25, 0.5, 0.75), "base_metalness": 0.5, "specular_roughness": 0.125,
                              "coat_weight": 1.0, "coat_ior": 1.5, "fuzz_weight": 0.25, "thin_film_thickness": 0.375},
                             {"base_color": [0.25, 0.5, 0.75], "base_metalness": 0.5, "specular_roughness": 0.125, "coat_weight": 1.0,
                              "coat_ior": 1.5, "fuzz_weight": 0.25, "thin_film_thickness": 0.375}),
        "standard_surface": ({"base": 0.5, "base_color": mx.Color3(1.0, 0.5, 0.25), "metalness": 1.0, "specular_roughness": 0.25,
                              "coat": 0.5, "coat_color": mx.Color3(0.5, 1.0, 1.0)},
                             # the translation graph: base_color x mix(1, coat_color, coat); a coated metal has no coat on top
                             {"base_weight": 0.5, "base_color": [0.75, 0.5, 0.25], "base_metalness": 1.0, "specular_weight": 1.0,
                              "specular_roughness": 0.25, "coat_weight": 0.0}),
    }
    for category, (inputs, expected) in cases.items():
        doc = mx.createDocument()
        shader = doc.addNode(category, "SR_written", "surfaceshader")
        for name, value in inputs.items():
            shader.setInputValue(name, value)
        material = doc.addMaterialNode("M_written", shader)
        assert material
        path = os.path.join(folder, f"written_by_materialx_{category}.mtlx")
        mx.writeToXmlFile(doc, path)
        out = os.path.join(folder, f"written_by_materialx_{category}.json")
        subprocess.run([dtoadq, "convert", path, "-o", out, "--quiet"], check=True, stderr=subprocess.DEVNULL)
        with open(out) as f:
            preset = json.load(f)
        for key, value in expected.items():
            if preset.get(key) != value:
                failures.append(f"a {category} document written by MaterialX: {key} read as {preset.get(key)}, expected {value}")
    return failures, len(cases)


def main():
    dtoadq = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "cli", "dtoadq")
    library = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), library)
    validator = gltf_validators()
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        presets = []
        for path in sorted(glob.glob(os.path.join(ROOT, "presets", "*.json"))):
            with open(path) as f:
                if json.load(f).get("model") != "openpbr":
                    continue
            name = os.path.splitext(os.path.basename(path))[0]
            for extension in ("mtlx", "gltf"):
                out = os.path.join(folder, f"{name}.{extension}")
                subprocess.run([dtoadq, "convert", path, "-o", out, "--quiet"], check=True, stderr=subprocess.DEVNULL)
            presets.append(name)
        # and a material with every glTF extension the writer uses (transmission is in no preset)
        everything = {"model": "openpbr", "base_color": [1, 1, 1], "base_metalness": 0.25, "specular_roughness": 0.4,
                      "specular_roughness_anisotropy": 0.5, "specular_ior": 1.7, "specular_weight": 0.8,
                      "transmission_weight": 0.6, "coat_weight": 0.8, "coat_roughness": 0.15, "coat_ior": 1.5,
                      "fuzz_weight": 1, "fuzz_color": [0.3, 0.2, 0.1], "thin_film_weight": 0.9,
                      "thin_film_thickness": 0.35, "emission_luminance": 12.5, "emission_color": [1, 0.5, 0.25]}
        with open(os.path.join(folder, "everything.json"), "w") as f:
            json.dump(everything, f)
        for extension in ("mtlx", "gltf"):
            subprocess.run([dtoadq, "convert", os.path.join(folder, "everything.json"), "-o", os.path.join(folder, f"everything.{extension}"),
                            "--quiet"], check=True, stderr=subprocess.DEVNULL)
        with open(os.path.join(folder, "everything.gltf")) as f:
            if len(json.load(f)["extensionsUsed"]) != 8:
                failures.append("the material meant to use every extension does not")
        if len(presets) < 7:
            failures.append(f"only {len(presets)} openpbr presets found")

        # the validators refuse broken variants of the first preset's files
        first = os.path.join(folder, presets[0])
        with open(first + ".mtlx") as f:
            text = f.read()
        shader = "SR_" + presets[0]
        broken_mtlx = {
            "an input of the wrong type": text.replace('name="coat_weight" type="float"', 'name="coat_weight" type="color3"', 1),
            "an unknown input": text.replace('name="base_weight"', 'name="base_wieght"', 1),
            "a dangling shader reference": text.replace(f'nodename="{shader}"', 'nodename="SR_nothing"', 1),
        }
        for what, variant in broken_mtlx.items():
            assert variant != text, what
            path = os.path.join(folder, "broken.mtlx")
            with open(path, "w") as f:
                f.write(variant)
            if not mtlx_problems(path, library):
                failures.append(f"MaterialX's validation accepted a document with {what}")
        with open(first + ".gltf") as f:
            doc = json.load(f)
        variants = {}
        variants["a roughness of 2"] = copy.deepcopy(doc)
        variants["a roughness of 2"]["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 2
        variants["no asset"] = copy.deepcopy(doc)
        del variants["no asset"]["asset"]
        variants["a negative clearcoat"] = copy.deepcopy(doc)
        variants["a negative clearcoat"]["materials"][0].setdefault("extensions", {})["KHR_materials_clearcoat"] = {"clearcoatFactor": -1}
        variants["a negative clearcoat"].setdefault("extensionsUsed", []).append("KHR_materials_clearcoat")
        variants["an extension missing from extensionsUsed"] = copy.deepcopy(doc)
        variants["an extension missing from extensionsUsed"]["materials"][0].setdefault("extensions", {})["KHR_materials_ior"] = {"ior": 1.4}
        for what, variant in variants.items():
            if not gltf_problems(variant, validator):
                failures.append(f"the glTF checks accepted a document with {what}")

        written_failures, written = materialx_written_documents_read_back(dtoadq, folder)
        failures += written_failures

        for name in presets + ["everything"]:
            problems = mtlx_problems(os.path.join(folder, name + ".mtlx"), library)
            with open(os.path.join(folder, name + ".gltf")) as f:
                problems += gltf_problems(json.load(f), validator)
            failures += [f"{name}: {p}" for p in problems]
            print(f"{name}: .mtlx and .gltf {'valid' if not problems else 'INVALID'}")
    for failure in failures:
        print("check_interchange_validity: " + failure, file=sys.stderr)
    print(f"check_interchange_validity: MaterialX {mx.getVersionString()}, jsonschema {importlib.metadata.version('jsonschema')}: "
          f"{len(presets)} presets and one material with every extension, {len(broken_mtlx) + len(variants)} broken variants refused, "
          f"{written} documents written by MaterialX read back, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
