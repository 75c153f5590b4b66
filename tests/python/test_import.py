"""Importing railjoint, and running the models, loads no GL and no MPI: a
notebook that never draws pays for neither (as the `railjoint` executable,
which loads GL only when it draws and has no MPI, scenes/CMakeLists.txt)."""

import subprocess
import sys

from conftest import SOURCE_DIR

# Shared objects that must not be mapped: OSMesa and its LLVM, EGL and GL, Open MPI.
FORBIDDEN = ("libOSMesa", "libEGL", "libGL", "libgallium", "libLLVM", "libmpi", "libopen-rte", "libopen-pal")

PROBE = """
import railjoint
scene = railjoint.load_scene({path!r})
railjoint.analytic(scene)
railjoint.simulate(scene)
railjoint.pressure(railjoint.load_scene({pressure_path!r}))
railjoint.sweep(scene, {{"wheel.y": [0.0, 0.01]}}, run=["analytic", "simulate"], jobs=2)
print(open("/proc/self/maps").read())
"""


def test_the_module_maps_no_gl_and_no_mpi():
    path = str(SOURCE_DIR / "scenes" / "default.toml")
    pressure_path = str(SOURCE_DIR / "scenes" / "pressure" / "table6_1.toml")
    probe = PROBE.format(path=path, pressure_path=pressure_path)
    maps = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    libraries = sorted({line.split()[-1] for line in maps.splitlines() if ".so" in line})
    print("\n".join(libraries))
    assert any("railjoint" in lib for lib in libraries), "the probe did not load the module"
    loaded = [lib for lib in libraries if any(name in lib for name in FORBIDDEN)]
    assert loaded == []


def test_every_function_and_class_has_a_docstring():
    import railjoint
    for name in ("load_scene", "Scene", "analytic", "Prediction", "simulate", "Simulation", "pressure", "Pressure",
                 "sweep"):
        assert getattr(railjoint, name).__doc__, name
