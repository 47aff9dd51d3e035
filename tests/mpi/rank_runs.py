"""What the MPI output tests share: a bundled scene run on 1 rank (plain)
and on 2 ranks (the MPI launcher), each in its own directory, and the files
and tables it wrote."""
import csv
import os
import shutil
import subprocess
import sys

# prm/pile-capacity.prm cut to n = 0, 1, 2 and 4 displacement steps to
# u = 0.02 d, with Soil plasticity/Stiffness = %s: a plastic run on 2 ranks
# in about 2 s (rank 0 owns n = 0 and 2, rank 1 the loaded n = 1).
PILE_SLICE_N2 = """
subsection Discretization
  set Harmonics = 0, 1, 2
end
subsection Load path
  set Load steps = 4
  set Target     = 0.02
end
subsection Soil plasticity
  set Stiffness = %s
end
subsection Output
  set Directory = out
end
"""

# The same slice in multi-surface (iwan) clay through one cycle, u = +0.02,
# -0.02, +0.02 m in 3 Newton steps a segment: every soil point carries its
# surfaces' back-stresses from step to step, and the reversals exercise
# Masing's rules (doc/soil-plasticity.md section 10). G0 gref = 3 s_u.
PILE_SLICE_N2_IWAN_CYCLE = """
subsection Discretization
  set Harmonics = 0, 1, 2
end
subsection Load path
  set Load steps = 3
  set Target     = 0
  set Targets    = 0.02, -0.02, 0.02
end
subsection Soil plasticity
  set Laws      = 0: iwan, su=10, gref=0.01, surfaces=8
  set Stiffness = tangent
end
subsection Output
  set Directory = out
end
"""

# The same cycle in multi-surface sand (iwan-sand, doc/soil-plasticity.md
# section 11): 6 Mohr-Coulomb elements whose strength c' = 10 kPa needs no
# initial stress; each sample carries its elements' plastic strains.
PILE_SLICE_N2_IWAN_SAND_CYCLE = PILE_SLICE_N2_IWAN_CYCLE.replace(
    "0: iwan, su=10, gref=0.01, surfaces=8",
    "0: iwan-sand, c=10, phi=20, psi=0, rf=0.9, surfaces=6")


def run(command, directory):
    """Runs command in directory, its output kept in log.txt; exits on
    failure (one FAIL line with the output)."""
    result = subprocess.run(command, cwd=directory, capture_output=True,
                            text=True, timeout=50)
    with open(os.path.join(directory, "log.txt"), "w") as out:
        out.write(result.stdout + result.stderr)
    if result.returncode != 0:
        sys.exit(f"FAIL {' '.join(command)}: exit {result.returncode}\n"
                 f"{result.stdout}{result.stderr}")
    return result.stdout


def table(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def on_one_and_two_ranks(argv, scene, appended, distribution):
    """argv = (script, MPIEXEC;-N;2, EXE, SOURCE, WORK): runs SOURCE/scene
    with `appended` (a later subsection wins in deal.II's ParameterHandler;
    it must set Output/Directory = out) on 1 and 2 ranks under WORK.
    The 2-rank log must contain `distribution`. Returns {ranks: out dir}."""
    mpiexec, exe, source, work = argv[1].split(";"), *argv[2:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(os.path.join(source, scene)) as f:
        text = f.read()
    outputs = {}
    for ranks in (1, 2):
        directory = os.path.join(work, f"ranks{ranks}")
        os.makedirs(directory)
        prm = os.path.join(directory, os.path.basename(scene))
        with open(prm, "w") as f:
            f.write(text + appended)
        launcher = [] if ranks == 1 else mpiexec
        log = run(launcher + [exe, prm], directory)
        outputs[ranks] = os.path.join(directory, "out")
        if ranks == 2 and distribution not in log:
            sys.exit("FAIL the 2-rank log does not name the distribution")
    return outputs


def wrote_exactly(outputs, expected):
    """Failures: runs whose output directory holds other files than
    `expected` (a set of names)."""
    failures = 0
    for ranks, directory in outputs.items():
        files = set(os.listdir(directory))
        ok = files == expected
        print(f"  {'ok  ' if ok else 'FAIL'} {ranks} rank(s) wrote "
              f"{sorted(files)}")
        failures += not ok
    return failures
