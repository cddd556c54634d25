# SPDX-License-Identifier: GPL-2.0-or-later
"""`import labelmesher` from an installed tree, not the build tree: `cmake --install` into a
scratch prefix, then a fresh interpreter with only that prefix's dist-packages on PYTHONPATH
reads a label image, meshes it and writes .msh through the package's reader, pipeline and writer
(the README's shortest pipeline), and gmsh checks the file.

Run by ctest (label "python") with LABELMESHER_BUILD_DIR set to the build tree."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
RAT_HEAD = os.path.join(HERE, "..", "..", "..", "shared", "data", "3d", "iso2mesh_rat_head.nrrd")

PIPELINE = """
import sys
import labelmesher
assert labelmesher.__file__.startswith(sys.argv[3]), labelmesher.__file__
reader = labelmesher.vtkLabelImageReader()
reader.SetFileName(sys.argv[1])
mesher = labelmesher.vtkLabelMesher()
mesher.SetInputConnection(reader.GetOutputPort())
writer = labelmesher.vtkLabelMeshWriter()
writer.SetInputConnection(mesher.GetOutputPort())
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)
"""


class InstalledTreeTest(unittest.TestCase):
    def test_import_mesh_and_write_from_the_installed_tree(self):
        build = os.environ["LABELMESHER_BUILD_DIR"]
        with tempfile.TemporaryDirectory() as prefix:
            install = subprocess.run(["cmake", "--install", build, "--prefix", prefix],
                                     capture_output=True, text=True)
            self.assertEqual(install.returncode, 0, install.stderr)
            packages = os.path.join(prefix, "lib", "python3", "dist-packages")
            self.assertTrue(os.path.isfile(os.path.join(packages, "labelmesher", "__init__.py")))
            out = os.path.join(prefix, "rat_head.msh")
            env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
            env["PYTHONPATH"] = packages
            run = subprocess.run([sys.executable, "-c", PIPELINE, RAT_HEAD, out, packages],
                                 capture_output=True, text=True, env=env, cwd=prefix)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            gmsh = shutil.which("gmsh")
            self.assertIsNotNone(gmsh, "gmsh is a test dependency")
            check = subprocess.run([gmsh, out, "-check"], capture_output=True, text=True)
            self.assertEqual(check.returncode, 0, check.stdout + check.stderr)
            self.assertNotIn("Error", check.stdout + check.stderr)


if __name__ == "__main__":
    unittest.main()
