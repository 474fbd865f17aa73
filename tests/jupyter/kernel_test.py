"""The chasles kernel over the Jupyter messaging protocol: jupyter_kernel_test's
suite (kernel_info, execute, errors, completion, inspection, is_complete,
history), then interrupts. Run by tests/jupyter.rs with JUPYTER_DATA_DIR naming
a folder where `chasles kernel install --user` put the kernelspec."""

import signal
import time
import unittest

import jupyter_kernel_test as jkt
from jupyter_client.manager import start_new_kernel


class ChaslesKernelTests(jkt.KernelTests):
    kernel_name = "chasles"
    language_name = "chasles"
    file_extension = ".chs"

    # A rotation 1e-3 off SO(3) is projected with a warning on stderr.
    code_stderr = "R_sb = [1, 0, 0; 0, 1, 0; 0, 0, 1.001]"

    completion_samples = [
        {"text": "MatrixLo", "matches": {"MatrixLog3(", "MatrixLog6("}},
        {"text": ":exa", "matches": {":exact"}},
    ]

    complete_code_samples = ["x = 1", "T = [1, 0; 0, 1]", ":exact", "R = [1, 0, 0\n0, 1, 0\n0, 0, 1]"]
    incomplete_code_samples = ["T = [1, 0", "exp([S] (theta", "mech < links 4; joints 4R"]

    code_generate_error = "undefined_name + 1"

    code_execute_result = [
        {"code": "1 + 2", "result": "3"},
        {"code": "Rotz(0)", "mime": "text/latex"},
        {"code": "RpToTrans(Rotz(0), (1, 2, 3))", "mime": "application/json"},
    ]

    code_display_data = [{"code": "a = 1\nb = 2", "mime": "text/plain"}]

    # `search` is not offered: jupyter-protocol 2.0 cannot read a search
    # request without `n` and `unique`, which jupyter_client leaves out.
    supported_history_operations = ("tail", "range")

    code_inspect_sample = "Rotz"

    def test_execute_result_values(self):
        self.flush_channels()
        reply, outs = self.execute_helper("T_sb = RpToTrans(Rotz(90 deg), (1, 2, 0))")
        self.assertEqual(reply["content"]["status"], "ok")
        data = outs[-1]["content"]["data"]
        self.assertIn("\\begin{bmatrix}", data["text/latex"])
        self.assertIn("SE(3)", data["text/latex"])
        self.assertEqual(data["application/json"]["frames"], ["s", "b"])
        self.assertTrue(data["text/plain"].endswith(": SE(3) {s}←{b}"))

    def test_frame_error_reads_as_in_the_terminal(self):
        self.flush_channels()
        self.execute_helper("T_ab = RpToTrans(Rotz(1), (1, 0, 0))\nT_cb = RpToTrans(Rotz(2), (0, 1, 0))")
        reply, outs = self.execute_helper("T_ab * T_cb")
        content = reply["content"]
        self.assertEqual(content["status"], "error")
        self.assertEqual(content["ename"], "frame")
        self.assertIn("frames do not cancel", content["evalue"])
        tb = "\n".join(content["traceback"])
        self.assertIn("T_ab * T_cb", tb)
        self.assertIn("^", tb)
        self.assertIn("help:", tb)
        # The bindings survive the error.
        reply, outs = self.execute_helper("T_ab * inv(T_cb)")
        self.assertEqual(reply["content"]["status"], "ok")


class InterruptTests(unittest.TestCase):
    """A cell that would run for many seconds stops on interrupt_request (and
    on SIGINT); the next cell sees the bindings made before it."""

    LONG = "y = 1\nlen([det(k*eye(60)) for k in 1:20000])"

    @classmethod
    def setUpClass(cls):
        cls.km, cls.kc = start_new_kernel(kernel_name="chasles")

    @classmethod
    def tearDownClass(cls):
        cls.kc.stop_channels()
        cls.km.shutdown_kernel()

    def run_cell(self, code, timeout=30):
        return self.kc.execute_interactive(code, timeout=timeout, output_hook=lambda m: None)

    def interrupted(self, interrupt):
        self.assertEqual(self.run_cell("x = 5")["content"]["status"], "ok")
        self.kc.execute(self.LONG)
        time.sleep(1.0)
        started = time.time()
        interrupt()
        reply = self.kc.get_shell_msg(timeout=30)
        self.assertLess(time.time() - started, 10)
        self.assertEqual(reply["content"]["status"], "error")
        self.assertEqual(reply["content"]["ename"], "interrupted")
        results = []
        reply = self.kc.execute_interactive(
            "x + y", timeout=30,
            output_hook=lambda m: results.append(m) if m["msg_type"] == "execute_result" else None)
        self.assertEqual(reply["content"]["status"], "ok")
        self.assertEqual(results[0]["content"]["data"]["text/plain"], "6")

    def test_interrupt_request(self):
        # The kernelspec's interrupt_mode is "message": an interrupt_request.
        self.interrupted(self.km.interrupt_kernel)

    def test_sigint(self):
        self.interrupted(lambda: self.km.signal_kernel(signal.SIGINT))


if __name__ == "__main__":
    unittest.main(verbosity=2)
