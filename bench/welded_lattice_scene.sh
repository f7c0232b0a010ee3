# Sourced by the benchmark scripts that run the welded square lattice of
# issue 37 as a scene: beams of 0.1 m in 10 segments, EA = 1e5, EI1 = 400,
# EI2 = 100, GJ = 67, pinned at its four corners, gravity on 0.05 kg/m in 2
# load steps, no VTU and no plot.

# welded_lattice_scene CELLS SOLVER_ENTRIES: the scene at CELLS x CELLS
# cells, with SOLVER_ENTRIES (lines "set Entry = value") in its Solver
# subsection.
welded_lattice_scene() {
  cat <<END
subsection Geometry
  set Generator = square lattice
  set Cells = $1, $1
  set Beam length = 0.1
  set Segments = 10
end
subsection Material
  subsection linear elastic
    set Stiffness input = direct
    set EA = 1e5
    set EI1 = 400
    set EI2 = 100
    set GJ = 67
  end
end
subsection Supports
  set Pinned vertices = @n_0_0, @n_$1_0, @n_0_$1, @n_$1_$1
end
subsection Loads
  set Steps = 2
  set Mass per length = 0.05
  set Gravity = 0, 0, -9.81
end
subsection Solver
$2
end
subsection Output
  set Write VTU = false
  set Plot = false
end
END
}
