"""scenewright's CAD worker: runs generated CadQuery and OpenSCAD code in a sandbox.

`worker.py` is the long-lived process (one per pool slot), `policy.py` the syntax-tree
check that runs before any code, `sandbox.py` the operating-system layers applied to each
job's process. The Rust side (`crates/sw_forge/src/runner`) starts workers with
`cad_worker.py --root DIR` and speaks JSON lines with them.
"""
