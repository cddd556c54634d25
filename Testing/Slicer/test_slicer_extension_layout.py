# SPDX-License-Identifier: GPL-2.0-or-later
"""SlicerModule/ as Slicer's extension templates lay it out, checked without Slicer:
the extension CMake's metadata and macros, the scripted module's classes, every
SlicerParameterName in the .ui naming a field of the @parameterNodeWrapper class
(and every field having a widget), and every Python file compiling."""
import ast
import os
import py_compile
import re
import unittest
import xml.etree.ElementTree as ET

SOURCE = os.environ.get("LABELMESHER_SOURCE", os.path.join(os.path.dirname(__file__), "../.."))
EXTENSION = os.path.join(SOURCE, "SlicerModule")
MODULE = os.path.join(EXTENSION, "LabelMesher")


def read(*parts):
    with open(os.path.join(*parts), encoding="utf-8") as f:
        return f.read()


class ExtensionLayoutTest(unittest.TestCase):

    def test_extension_cmake(self):
        text = read(EXTENSION, "CMakeLists.txt")
        for variable in ("HOMEPAGE", "CATEGORY", "CONTRIBUTORS", "DESCRIPTION", "ICONURL", "SCREENSHOTURLS",
                         "DEPENDS"):
            self.assertRegex(text, rf"set\(EXTENSION_{variable} ", variable)
        for line in ("find_package(Slicer REQUIRED)", "include(${Slicer_USE_FILE})",
                     "include(${Slicer_EXTENSION_GENERATE_CONFIG})", "include(${Slicer_EXTENSION_CPACK})",
                     "add_subdirectory(LabelMesher)"):
            self.assertIn(line, text)
        module = read(MODULE, "CMakeLists.txt")
        self.assertRegex(module, r"slicerMacroBuildScriptedModule\([^)]*WITH_GENERIC_TESTS", module)
        for resource in re.findall(r"Resources/\S+", module):
            path = os.path.join(MODULE, resource.replace("${MODULE_NAME}", "LabelMesher"))
            self.assertTrue(os.path.isfile(path), path)
        for script in re.findall(r"\$\{MODULE_NAME\}\S*\.py", module):
            self.assertTrue(os.path.isfile(os.path.join(MODULE, script.replace("${MODULE_NAME}", "LabelMesher"))))

    def test_module_classes_and_parameter_names(self):
        tree = ast.parse(read(MODULE, "LabelMesher.py"))
        classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
        for name in ("LabelMesher", "LabelMesherWidget", "LabelMesherLogic", "LabelMesherTest",
                     "LabelMesherParameterNode"):
            self.assertIn(name, classes)
        wrapper = classes["LabelMesherParameterNode"]
        self.assertIn("parameterNodeWrapper", [getattr(d, "id", None) for d in wrapper.decorator_list])
        fields = {node.target.id for node in wrapper.body if isinstance(node, ast.AnnAssign)}
        ui = ET.parse(os.path.join(MODULE, "Resources/UI/LabelMesher.ui"))
        named = {prop.find("string").text for prop in ui.iter("property")
                 if prop.get("name") == "SlicerParameterName"}
        self.assertEqual(named, fields)
        widgets = {w.get("name") for w in ui.iter("widget")}
        used = set(re.findall(r"self\.ui\.(\w+)", read(MODULE, "LabelMesher.py")))
        self.assertLessEqual(used, widgets, "the widget uses names the .ui does not have")

    def test_every_python_file_compiles(self):
        files = [os.path.join(d, f) for d, _, names in os.walk(EXTENSION) for f in names if f.endswith(".py")]
        self.assertGreaterEqual(len(files), 3)
        for path in files:
            with self.subTest(path=path):
                py_compile.compile(path, doraise=True)


if __name__ == "__main__":
    unittest.main()
