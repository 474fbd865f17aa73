"""notebooks/ch3_tour.ipynb executed end to end by nbclient on the chasles
kernel, its outputs checked: a picture as SVG, LaTeX matrices, the frame
error as an error output, Example 3.2's values as the terminal prints them,
the mechanism's dof, no file written, and the committed outputs the same
as this fresh run's (CHASLES_UPDATE_NOTEBOOK=1 rewrites them). Run by tests/jupyter.rs (env
CHASLES_BIN, JUPYTER_DATA_DIR; the working folder is a fresh temporary one)."""

import os
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

import nbclient
import nbformat

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NOTEBOOK = os.path.join(ROOT, "notebooks", "ch3_tour.ipynb")


def shown(cell):
    """What a cell's outputs show (text, LaTeX, SVG, errors), without the
    counters and ids that change from run to run, nor the application/json
    a reader does not see."""
    out = []
    for o in cell.outputs:
        if o.output_type == "stream":
            out.append((o.name, o.text))
        elif o.output_type == "error":
            out.append(("error", o.ename, o.evalue))
        else:
            out.append((o.output_type, {k: v for k, v in o.data.items() if k != "application/json"}))
    return out


class TourNotebook(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.before = set(os.listdir("."))
        cls.committed = [c for c in nbformat.read(NOTEBOOK, as_version=4).cells if c.cell_type == "code"]
        nb = nbformat.read(NOTEBOOK, as_version=4)
        for cell in nb.cells:
            if cell.cell_type == "code":
                cell.outputs = []
        nbclient.NotebookClient(nb, timeout=120, kernel_name="chasles", record_timing=False).execute()
        if os.environ.get("CHASLES_UPDATE_NOTEBOOK"):
            # Rewrites the committed outputs with this run's (then commit it).
            nbformat.write(nb, NOTEBOOK)
        cls.cells = [c for c in nb.cells if c.cell_type == "code"]

    def tagged(self, tag):
        return [c for c in self.cells if tag in c.metadata.get("tags", [])]

    def outputs(self, cells, kind=None):
        return [o for c in cells for o in c.outputs if kind is None or o.output_type == kind]

    def test_the_picture_is_inline_svg(self):
        (cell,) = self.tagged("picture")
        svgs = [o.data["image/svg+xml"] for o in cell.outputs if "data" in o and "image/svg+xml" in o.data]
        self.assertEqual(len(svgs), 1)
        root = ET.fromstring(svgs[0])
        self.assertTrue(root.tag.endswith("svg"), root.tag)
        self.assertGreater(len(list(root.iter())), 20)

    def test_matrices_are_latex(self):
        latex = [o.data["text/latex"] for o in self.outputs(self.cells) if "data" in o and "text/latex" in o.data]
        self.assertTrue(any("bmatrix" in t for t in latex))
        (cell,) = self.tagged("closed-form")
        (result,) = self.outputs([cell], "execute_result")
        self.assertIn("\\begin{bmatrix}", result.data["text/latex"])
        self.assertIn("\\cos", result.data["text/latex"])

    def test_the_frame_error_is_an_error_output(self):
        (cell,) = self.tagged("frame-error")
        (err,) = self.outputs([cell], "error")
        self.assertEqual(err.ename, "frame")
        self.assertIn("frames do not cancel", err.evalue)
        self.assertIn("T_ab * T_ce", "\n".join(err.traceback))
        # The cell after it (the fix) ran and bound T_ae.
        after = self.cells[self.cells.index(cell) + 1]
        self.assertEqual(self.outputs([after], "error"), [])

    def test_example_3_2_matches_the_terminal(self):
        cells = self.tagged("example-3.2")
        script = "\n".join(c.source for c in cells) + "\n"
        terminal = subprocess.run(
            [os.environ["CHASLES_BIN"], "run", "-"], input=script, capture_output=True, text=True, check=True
        ).stdout
        shown = "".join(
            o.data["text/plain"] + "\n" for o in self.outputs(cells) if "data" in o
        )
        self.assertEqual(shown, terminal)
        self.assertIn("113.1371", shown)  # 160/√2, the book's slip corrected

    def test_the_mechanism_has_six_dof(self):
        (cell,) = self.tagged("dof")
        (result,) = self.outputs([cell], "execute_result")
        self.assertEqual(result.data["text/plain"], "6")
        self.assertTrue(any("dof = 6(14 − 1 − 18)" in o.data["text/plain"] for o in self.outputs([cell]) if "data" in o))

    def test_the_committed_outputs_are_a_fresh_runs(self):
        # GitHub renders the committed outputs: they must be what the kernel
        # shows now (rewrite them with CHASLES_UPDATE_NOTEBOOK=1).
        self.assertEqual(len(self.committed), len(self.cells))
        for i, (old, new) in enumerate(zip(self.committed, self.cells)):
            self.assertEqual(
                shown(old),
                shown(new),
                f"code cell {i + 1} ({old.source[:40]!r}): its committed outputs differ from a fresh run; "
                "rerun tests/jupyter.rs with CHASLES_UPDATE_NOTEBOOK=1 and commit the notebook",
            )

    def test_no_file_was_written(self):
        self.assertEqual(set(os.listdir(".")) - self.before, set())


if __name__ == "__main__":
    unittest.main(verbosity=2)
