# Sourced by the benchmark scripts that run the elastica's rod (B = L = 1,
# EI2 = 2 EI1, clamped at its start half a segment behind x = 0).
#
# elastica_scene N INEXTENSIBLE EA BLOCKS PROBES: the scene with N segments,
# Material/Inextensible INEXTENSIBLE, the stiffness EA, the subsections
# BLOCKS (loads and solver) and the Output/Probes PROBES, without VTU output
# or plots.
elastica_scene() {
  cat <<END
subsection Geometry
  set Generator = straight
  set Segments = $1
  set Clamp at first segment midpoint = true
  set Director d1 = 0, 0, 1
end
subsection Material
  set Inextensible = $2
  subsection linear elastic
    set Stiffness input = direct
    set EA = $3
    set EI1 = 1
    set EI2 = 2
    set GJ = 1
  end
end
subsection Supports
  set Clamped ends = start
end
$4
subsection Output
  set Write VTU = false
  set Plot = false
  set Probes = $5
end
END
}
