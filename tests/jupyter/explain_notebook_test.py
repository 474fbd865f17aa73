"""notebooks/explain.ipynb executed end to end by nbclient on the chasles
kernel (LANGUAGE.md §14): every `explain` cell's value is shown as LaTeX
(one align* with the book's references), as the terminal prints it in
text/plain, and with the JSON steps list; the half turn cites (3.60), the
SE(3) log G⁻¹ (3.94), the chain the cancelled subscripts, the symbolic
joint Prop. 3.16 and the mechanism Grübler's dof. Run by tests/jupyter.rs
(env CHASLES_BIN, JUPYTER_DATA_DIR; the working folder is a fresh one)."""

import os
import subprocess
import unittest

import nbclient
import nbformat

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NOTEBOOK = os.path.join(ROOT, "notebooks", "explain.ipynb")


class ExplainNotebook(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        nb = nbformat.read(NOTEBOOK, as_version=4)
        for cell in nb.cells:
            if cell.cell_type == "code":
                cell.outputs = []
        nbclient.NotebookClient(nb, timeout=120, kernel_name="chasles").execute()
        cls.cells = [c for c in nb.cells if c.cell_type == "code"]

    def result(self, tag):
        (cell,) = [c for c in self.cells if tag in c.metadata.get("tags", [])]
        self.assertEqual([o for o in cell.outputs if o.output_type == "error"], [])
        results = [o for o in cell.outputs if o.output_type == "execute_result"]
        return results[-1].data

    def steps(self, tag):
        return self.result(tag)["application/json"]["steps"]

    def test_every_explain_renders_as_latex(self):
        for tag in ["rodrigues", "half-turn", "log6", "chain", "symbolic", "dof"]:
            latex = self.result(tag)["text/latex"]
            self.assertTrue(latex.startswith("\\begin{align*}"), (tag, latex))
            self.assertIn("\\text{", latex)

    def test_the_half_turn_cites_3_60(self):
        steps = self.steps("half-turn")
        (w,) = [s for s in steps if s["name"] == "omega_hat"]
        self.assertEqual(w["ref"], "3.60")
        self.assertEqual(w["value"], [1, 0, 0])
        self.assertIn("(3.60)", self.result("half-turn")["text/latex"])

    def test_the_transform_log_shows_g_inverse(self):
        steps = {s["name"]: s for s in self.steps("log6")}
        self.assertEqual(steps["G_inv"]["ref"], "3.94")
        self.assertAlmostEqual(steps["theta"]["value"], 1.5707963267948966, places=12)
        self.assertEqual(steps["v"]["value"][0], 0)
        self.assertAlmostEqual(steps["v"]["value"][1], 1.5, places=12)

    def test_the_chain_cancels_in_order(self):
        steps = self.steps("chain")
        self.assertEqual([s["frames"] for s in steps if s["name"] == "chain"][-1], ["c", "e"])
        self.assertIn("{d} cancels", steps[0]["text"])

    def test_the_symbolic_joint_is_prop_3_16(self):
        steps = {s["name"]: s for s in self.steps("symbolic")}
        self.assertEqual(steps["q"]["value"], [0, 2, 0])
        self.assertEqual(steps["h"]["value"], 0)
        self.assertEqual(steps["T"]["ref"], "3.89")

    def test_the_dof_is_grubler(self):
        steps = {s["name"]: s for s in self.steps("dof")}
        self.assertEqual(steps["dof"]["ref"], "2.4")
        self.assertEqual(steps["dof"]["value"], 1)

    def test_text_is_the_terminal(self):
        cell = [c for c in self.cells if "half-turn" in c.metadata.get("tags", [])][0]
        terminal = subprocess.run(
            [os.environ["CHASLES_BIN"], "run", "-"], input=cell.source + "\n", capture_output=True, text=True, check=True
        ).stdout
        self.assertEqual(self.result("half-turn")["text/plain"] + "\n", terminal)


if __name__ == "__main__":
    unittest.main(verbosity=2)
