#!/usr/bin/env python3
"""tests/same_results.py finds every kind of difference, and none where there is none."""
import gzip
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from same_results import compare  # noqa: E402

RESULTS = "scene,scheme,dt,metric,value\na,x,0.1,omega_err_max,0.5\na,x,0.1,ns_per_step,80\n"
ORDERS = "scene,scheme,metric,status,order\na,x,omega_err_max,fit,2\n"
ANSWER = "tolerance,scene,scheme,how,dt,cpu_seconds\n0.001,a,x,interpolated,0.01,3e-5\n"
TIMING = {"ns_per_step"}


def folder(root, name, results=RESULTS, orders=ORDERS, answer=ANSWER, gzipped=False):
    path = Path(root) / name
    path.mkdir()
    if gzipped:
        with gzip.open(path / "results.csv.gz", "wt") as f:
            f.write(results)
    else:
        (path / "results.csv").write_text(results)
    if orders is not None:
        (path / "orders.csv").write_text(orders)
    (path / "answer.csv").write_text(answer)
    return path


class SameResults(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.TemporaryDirectory()
        self.base = folder(self.root.name, "base")

    def tearDown(self):
        self.root.cleanup()

    def test_equal_folders_agree_and_timing_is_left_out(self):
        new = folder(self.root.name, "new", results=RESULTS.replace(",80", ",95"), answer=ANSWER.replace("3e-5", "4e-5"))
        self.assertEqual(compare(self.base, new, TIMING), (3, []))  # the ns_per_step row is not compared

    def test_a_gzipped_base_reads_as_the_csv(self):
        zipped = folder(self.root.name, "zipped", gzipped=True)
        self.assertEqual(compare(zipped, self.base, TIMING)[1], [])

    def test_a_changed_value_differs(self):
        new = folder(self.root.name, "new", results=RESULTS.replace("0.5", "0.50000000000000011"))
        self.assertEqual(len(compare(self.base, new, TIMING)[1]), 1)

    def test_a_changed_status_differs(self):
        new = folder(self.root.name, "new", orders=ORDERS.replace("fit,2", "insufficient,"))
        self.assertEqual(len(compare(self.base, new, TIMING)[1]), 2)

    def test_a_missing_row_a_new_row_and_a_missing_file_differ(self):
        new = folder(self.root.name, "new", results=RESULTS.replace("a,x,0.1,omega", "a,y,0.1,omega"), orders=None)
        self.assertEqual(len(compare(self.base, new, TIMING)[1]), 3)

    def test_changed_columns_differ(self):
        new = folder(self.root.name, "new", orders=ORDERS.replace("order\n", "order_fit\n"))
        self.assertIn("columns", compare(self.base, new, TIMING)[1][0])


if __name__ == "__main__":
    unittest.main()
