"""The result types of the dtlab API, built from what the C++ core returns."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from . import _core, _meshio

DEFECT_KINDS: tuple[str, ...] = tuple(_core.defect_kinds())


class _Summary:
    """Notebook display of a result class: its one-line __repr__, HTML-escaped."""

    def _repr_html_(self) -> str:
        text = repr(self).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        return f"<code>{text}</code>"


class Mesh(NamedTuple):
    """A triangle mesh: (n, 3) float64 vertices and (m, 3) uint32 faces (0-based)."""

    vertices: np.ndarray
    faces: np.ndarray


@dataclass(frozen=True)
class Failure:
    """A named build failure: kind (walk-cycle, flip-stuck, inconsistent-adjacency,
    outside-boundary), the input index of the point being inserted (-1 if none), detail."""

    kind: str
    point: int
    detail: str

    def __str__(self) -> str:
        return f"{self.kind} while inserting point {self.point}: {self.detail}"


@dataclass(frozen=True, repr=False)
class Tetrahedralization(_Summary):
    """The Delaunay tetrahedralization of `points`.

    tets: (m, 4) uint32 input indices, every tet with orient3d > 0 (positive
    orientation, Shewchuk's convention). duplicates: input indices equal to an earlier
    point (never inserted). skipped: inputs not inserted because the build failed
    first. stats: the summary `dtlab tetra --json` prints (flips per kind, walk steps,
    predicate calls, adaptive stages, seconds, ...). failure: None, or the named failure
    the build stopped at (only with raise_on_failure=False; `tets` is then the mesh
    built so far).
    """

    points: np.ndarray
    tets: np.ndarray
    duplicates: np.ndarray
    skipped: np.ndarray
    stats: dict[str, Any]
    failure: Failure | None = None

    def __repr__(self) -> str:
        state = f"FAILED: {self.failure}" if self.failure else "built"
        return (f"<dtlab.Tetrahedralization: {len(self.points)} points, {len(self.tets)} tets, "
                f"{len(self.duplicates)} duplicates, {state} in {self.stats.get('seconds', 0):.3g} s "
                f"({self.stats.get('predicates', '?')} predicates)>")

    def to_meshio(self) -> Any:
        """A meshio.Mesh of the tets ("tetra" cells, VTK's order); needs meshio."""
        return _meshio.tetrahedralization_mesh(self.points, self.tets)


class BuildFailure(RuntimeError):
    """A build stopped at a named failure (non-robust predicates). `kind`, `point` and
    `detail` name it; `result` is the partial Tetrahedralization built so far."""

    def __init__(self, failure: Failure, result: Tetrahedralization):
        super().__init__(f"FAILURE {failure}")
        self.kind = failure.kind
        self.point = failure.point
        self.detail = failure.detail
        self.result = result


@dataclass(frozen=True)
class Defect:
    """One witness of a defect: its kind, what was expected, the tets (row indices into
    the tets array) and vertices (input indices) involved, and the exact sign of the
    deciding predicate (0 if none)."""

    kind: str
    detail: str
    tets: tuple[int, ...]
    vertices: tuple[int, ...]
    sign: int


@dataclass(frozen=True, repr=False)
class CheckReport(_Summary):
    """The exact checker's verdict on a tetrahedralization.

    ok: it is the Delaunay tetrahedralization of its points. verdict: one line.
    counts: every defect kind -> how many (all are counted). defects: witnesses, a
    few per kind. stats: what `dtlab check --json` reports (points, vertices, tets,
    facets, Euler characteristics, cospherical facets, exact volumes, seconds).
    orientation: the handedness the tets were read in ("positive", "negative", or
    "any": each tet by its own sign). swapped: tets whose first two vertices were
    swapped to bring them to orient3d > 0.
    """

    ok: bool
    verdict: str
    counts: dict[str, int]
    defects: list[Defect]
    stats: dict[str, Any]
    orientation: str
    swapped: int

    @classmethod
    def _from_raw(cls, raw: dict[str, Any]) -> CheckReport:
        raw = dict(raw)
        found = raw.pop("defect_counts")
        counts = {k: int(found.get(k, 0)) for k in DEFECT_KINDS}
        defects = [Defect(d["kind"], d["detail"], tuple(d["tets"]), tuple(d["vertices"]), d["sign"])
                   for d in raw.pop("defects")]
        ok = bool(raw.pop("valid"))
        if ok:
            verdict = "valid Delaunay tetrahedralization"
        else:
            verdict = "DEFECTS FOUND: " + ", ".join(f"{n} {k}" for k, n in counts.items() if n)
        orientation = raw.pop("orientation")
        swapped = int(raw.pop("swapped", 0))
        return cls(ok, verdict, counts, defects, raw, orientation, swapped)

    def __repr__(self) -> str:
        return (f"<dtlab.CheckReport: {self.verdict}; {self.stats.get('tets', '?')} tets, "
                f"{self.stats.get('seconds', 0):.3g} s>")


def _cell_text(cell: tuple[int, ...]) -> str:
    return "{" + " ".join(str(v) for v in cell) + "}"


@dataclass(frozen=True, repr=False)
class Comparison(_Summary):
    """Two tetrahedralizations of the same points compared canonically.

    verdict: "identical" (same tets), "same Delaunay complex" (the tets differ only
    inside cells of cospherical points, where a Delaunay tetrahedralization is not
    unique) or "different". detail: the line `dtlab oracle` prints for the pair.
    The complex is only compared when both meshes are valid (complexes_equal is None
    otherwise). only_a / only_b: a few Delaunay cells found in one mesh only.
    a, b: the check reports of both meshes (from dtlab.compare).
    """

    verdict: str
    detail: str
    tets_equal: bool
    complexes_equal: bool | None
    general_position: bool | None
    cells: tuple[int, int] | None
    only_a: list[tuple[int, ...]] = field(default_factory=list)
    only_b: list[tuple[int, ...]] = field(default_factory=list)
    a: CheckReport | None = None
    b: CheckReport | None = None

    @classmethod
    def _from_raw(cls, raw: dict[str, Any] | None, tets_equal: bool, a: CheckReport | None = None,
                  b: CheckReport | None = None) -> Comparison:
        if raw is None:  # a mesh is not valid: only the tets can be compared
            bad = [name for name, r in (("first", a), ("second", b)) if r is not None and not r.ok]
            why = f"the {' and '.join(bad)} mesh is not a valid Delaunay tetrahedralization"
            if tets_equal:
                return cls("identical", f"identical tets ({why})", True, None, None, None, a=a, b=b)
            return cls("different", f"DIFFER: {why}", False, None, None, None, a=a, b=b)
        only_a = [tuple(c) for c in raw["only_first"]]
        only_b = [tuple(c) for c in raw["only_second"]]
        cells = (int(raw["cells"][0]), int(raw["cells"][1]))
        gp, te, ce = bool(raw["general_position"]), bool(raw["tets_equal"]), bool(raw["complexes_equal"])
        if raw["agree"]:
            if gp:
                detail = "agree (general position: identical tets)"
            elif te:
                detail = f"agree (identical tets; {cells[0]} Delaunay cells)"
            else:
                detail = (f"agree (same Delaunay complex, {cells[0]} cells; "
                          "tets differ inside cospherical cells)")
        else:
            detail = (f"DIFFER: {raw['only_first_count']} cells only in the first, "
                      f"{raw['only_second_count']} only in the second")
            if only_a:
                detail += f"; e.g. first only {_cell_text(only_a[0])}"
            if only_b:
                detail += f"; e.g. second only {_cell_text(only_b[0])}"
        verdict = "identical" if te else "same Delaunay complex" if ce else "different"
        return cls(verdict, detail, te, ce, gp, cells, only_a, only_b, a, b)

    def __repr__(self) -> str:
        return f"<dtlab.Comparison: {self.verdict}: {self.detail}>"


@dataclass(frozen=True)
class OracleRun:
    """One producer in dtlab.oracle (dtlab itself or a peer): its verdict (delaunay,
    triangulation, flat-tets, invalid, unproven, missing-points, extra-points, crashed, hung,
    refused, not-installed), message (a refusal's text, a signal, a note), seconds,
    tets ((m, 4) uint32 over the input points, positive orientation, or None when it
    gave no answer), defects ({kind: count}), its exact check, and `agree` (whether
    dtlab's answer agrees with it; None when they were not compared). `raw` is the
    JSON object `dtlab oracle --json` prints for it."""

    name: str
    verdict: str
    message: str
    seconds: float
    tets: np.ndarray | None
    defects: dict[str, int]
    check: CheckReport | None
    agree: bool | None
    raw: dict[str, Any]


@dataclass(frozen=True, repr=False)
class OracleReport(_Summary):
    """dtlab.oracle's verdict, the same as `dtlab oracle --json`'s: ok, exit (0 ok;
    1 dtlab's result is wrong or differs from a proven peer; 3 some peer gave no
    answer), the problems found, the peers not compared (no answer, or a wrong one),
    dtlab's own run, every peer's run, and dtlab compared with every peer proven
    Delaunay ("dtlab vs cgal", ...)."""

    ok: bool
    exit: int
    problems: list[str]
    not_compared: list[str]
    dtlab: OracleRun
    peers: dict[str, OracleRun]
    comparisons: dict[str, Comparison]

    def __repr__(self) -> str:
        runs = ", ".join(f"{r.name} {r.verdict} {r.seconds:.3g} s" for r in [self.dtlab, *self.peers.values()])
        return f"<dtlab.OracleReport: {'ok' if self.ok else 'NOT OK'} (exit {self.exit}); {runs}>"


@dataclass(frozen=True)
class VoronoiCell:
    """The Voronoi cell of one site, clipped to the box.

    vertices: (k, 3) float64. faces: one uint32 array of vertex indices per face,
    counter-clockwise seen from outside. face_neighbors: per face, the site on its
    other side, or -1..-6 for the box walls x-lo, x-hi, y-lo, y-hi, z-lo, z-hi.
    neighbors: the sorted sites sharing a face. duplicate_of: for a repeated site
    (whose cell is empty) the site it repeats, else -1. The arrays are read-only views
    of the diagram's storage.
    """

    site: int
    vertices: np.ndarray
    faces: list[np.ndarray]
    face_neighbors: np.ndarray
    neighbors: np.ndarray
    volume: float
    centroid: tuple[float, float, float]
    duplicate_of: int


@dataclass(frozen=True, repr=False)
class VoronoiDiagram(_Summary):
    """Voronoi cells of every site, clipped to `box` ((xmin, ymin, zmin), (xmax, ymax,
    zmax)); `clipped`: cells built by the general clipping engine (hull sites, doubtful
    duals), `box_clipped`: dual cells then cut by the box walls."""

    box: tuple[tuple[float, float, float], tuple[float, float, float]]
    cells: list[VoronoiCell]
    tets: int
    clipped: int
    box_clipped: int
    seconds_delaunay: float
    seconds_cells: float

    def __repr__(self) -> str:
        volume = sum(c.volume for c in self.cells)
        return (f"<dtlab.VoronoiDiagram: {len(self.cells)} cells, volume {volume:.6g}, {self.tets} tets, "
                f"{self.seconds_delaunay:.3g} s Delaunay + {self.seconds_cells:.3g} s cells>")


@dataclass(frozen=True)
class Piece:
    """One closed piece of a fractured mesh.

    vertices (k, 3), faces (f, 3) outward-oriented; cut: bool mask of the faces that are
    cuts (interior faces of the object); cut_tag: per cut face the neighbouring site
    (or wall) whose bisector it lies on; volume, centroid, site, interior_area (area
    of the cut faces), neighbors (pieces sharing a cut face), parent (the top-level
    piece it was split from by `recurse`, else -1), site_index (its site among its
    level's) and island (its place among that site's islands, largest first). With
    fracture(..., tets=True): tet_points (q, 3), the piece's vertices first, bit for bit,
    then TetGen's Steiner points, and tets (m, 4) indices into them in dtlab's orientation
    (orient3d(a, b, c, d) > 0, i.e. det(b - a, c - a, d - a) < 0); else None.
    """

    vertices: np.ndarray
    faces: np.ndarray
    cut: np.ndarray
    cut_tag: np.ndarray
    volume: float
    centroid: tuple[float, float, float]
    site: tuple[float, float, float]
    interior_area: float
    neighbors: np.ndarray
    parent: int
    site_index: int = -1
    island: int = 0
    tet_points: np.ndarray | None = None
    tets: np.ndarray | None = None


class Pieces(list[Piece], _Summary):
    """The pieces of dtlab.fracture, a list, plus `mesh_volume`,
    `relative_volume_error` (|sum of piece volumes - mesh volume| / mesh volume) and the
    `manifest` `dtlab fracture --json` prints."""

    mesh_volume: float
    relative_volume_error: float
    manifest: dict[str, Any]

    def __repr__(self) -> str:
        seconds = getattr(self, "manifest", {}).get("seconds", {})  # per stage
        timing = f", {sum(seconds.values()):.3g} s" if isinstance(seconds, dict) and seconds else ""
        return (f"<dtlab.Pieces: {len(self)} pieces, mesh volume {getattr(self, 'mesh_volume', float('nan')):.6g}, "
                f"relative volume error {getattr(self, 'relative_volume_error', float('nan')):.2g}{timing}>")

    def to_meshio(self) -> Any:
        """One meshio.Mesh of all pieces' triangles, cell data "piece" and "cut"; needs meshio."""
        return _meshio.pieces_mesh(self)
