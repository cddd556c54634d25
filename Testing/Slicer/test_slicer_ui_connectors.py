# SPDX-License-Identifier: GPL-2.0-or-later
"""Every widget of LabelMesher.ui bound by SlicerParameterName is of a class that the
parameterNodeWrapper of both Slicer 5.6.2 and 5.8.1 can connect to its parameter's type.

connectGui() raises on the first widget no connector accepts, so a class only 5.8 knows
(ctkDoubleSpinBox for a float) breaks the module's setup() in 5.6. The connectors' class
lists are data (Data/parameter_node_gui_connectors.json, copied from Slicer's
guiConnectors.py at both tags); the parameter types come from LabelMesher.py's
@parameterNodeWrapper class.
"""
import ast
import json
import os
import unittest
import xml.etree.ElementTree as ET

SOURCE = os.environ.get("LABELMESHER_SOURCE", os.path.join(os.path.dirname(__file__), "../.."))
MODULE = os.path.join(SOURCE, "SlicerModule", "LabelMesher")
CONNECTORS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Data", "parameter_node_gui_connectors.json")


def parameter_kinds(module_path):
    """{field: 'bool' | 'int' | 'float' | 'str' | 'node'} of the @parameterNodeWrapper class."""
    tree = ast.parse(open(module_path, encoding="utf-8").read())
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and any(getattr(d, "id", None) == "parameterNodeWrapper"
                                                   for d in node.decorator_list):
            return {field.target.id: annotation_kind(field.annotation)
                    for field in node.body if isinstance(field, ast.AnnAssign)}
    raise AssertionError("no @parameterNodeWrapper class in " + module_path)


def annotation_kind(annotation):
    if isinstance(annotation, ast.Subscript) and getattr(annotation.value, "id", None) == "Annotated":
        return annotation_kind(annotation.slice.elts[0])  # Annotated[float, WithinRange(...)]: float
    if isinstance(annotation, ast.Name):
        return annotation.id
    if isinstance(annotation, ast.Attribute) and annotation.attr.startswith("vtkMRML"):
        return "node"
    raise AssertionError("unexpected annotation " + ast.dump(annotation))


def bound_widgets(ui_path):
    """{parameter name: widget class} for every widget with a SlicerParameterName."""
    bound = {}
    for widget in ET.parse(ui_path).iter("widget"):
        for prop in widget.findall("property"):
            if prop.get("name") == "SlicerParameterName":
                bound[prop.find("string").text] = widget.get("class")
    return bound


class UiConnectorConformanceTest(unittest.TestCase):

    def test_every_bound_widget_connects_in_both_versions(self):
        versions = json.load(open(CONNECTORS, encoding="utf-8"))["versions"]
        self.assertEqual(sorted(versions), ["5.6.2", "5.8.1"])
        kinds = parameter_kinds(os.path.join(MODULE, "LabelMesher.py"))
        widgets = bound_widgets(os.path.join(MODULE, "Resources", "UI", "LabelMesher.ui"))
        self.assertEqual(set(widgets), set(kinds), "the .ui and the parameter class name different parameters")
        for version, accepted in versions.items():
            for name, widget_class in sorted(widgets.items()):
                with self.subTest(version=version, parameter=name):
                    self.assertIn(widget_class, accepted[kinds[name]],
                                  f"Slicer {version} has no connector from {widget_class} to {kinds[name]} ({name})")


if __name__ == "__main__":
    unittest.main()
