"""covopt.Catalog: the built-in catalog and users' catalog files (the same TOML keys, among them
the compressive curves), as ``covopt materials ... --catalog FILE``."""

import os

from . import _covopt
from ._results import Material


class Found(list):
    """Catalog.find's answer: the Materials that match, in catalog order, and
    ``excluded_for_want_of_curve``: how many that pass every other condition were left out
    because they have no compressive curve (through 25 % for stress_at_25)."""

    def __init__(self, materials, excluded_for_want_of_curve):
        super().__init__(materials)
        self.excluded_for_want_of_curve = excluded_for_want_of_curve


class Catalog:
    """A catalog: the built-in one (unless ``no_builtin=True``) and the catalog files given, in
    order, as ``--catalog FILE`` on the CLI. A file that cannot be read or is not a valid
    catalog raises ValueError "catalog: file:line:column: ..." naming the key, the value and what
    is allowed; a name defined twice raises ValueError naming both places."""

    def __init__(self, *files, no_builtin=False):
        names = []
        for file in files:
            if not isinstance(file, (str, os.PathLike)):
                raise TypeError(f"Catalog: expected catalog file names (got {file!r})")
            names.append(os.fspath(file))
        self._files = names
        self._no_builtin = bool(no_builtin)
        self._rows = _covopt.catalog_materials(self._files, self._no_builtin)  # checks the files now

    @property
    def files(self):
        """The catalog files, in order."""
        return list(self._files)

    def materials(self):
        """Every material, in catalog order, as ``covopt materials list --json``."""
        return [Material(dict(row)) for row in self._rows]

    def material(self, name):
        """One material by name (ignoring case); an unknown name raises ValueError with the
        CLI's "did you mean" suggestions."""
        return Material(_covopt.catalog_material(self._files, self._no_builtin, name))

    def find(self, *, stress_at_25=None, has_curve=False, family=None, name=None):
        """The materials that pass every condition given, as ``covopt materials find --json``:
        ``stress_at_25=(low_Pa, high_Pa)`` keeps those whose compressive curve's stress at 25 %
        strain is in range (None for an open end; materials without a curve through 25 % never
        pass it), ``has_curve=True`` those with a curve, ``family`` a family or a list of them,
        ``name`` those whose name contains it (ignoring case). Returns a list of Materials with
        ``excluded_for_want_of_curve``, the number left out for want of a curve."""
        families = [family] if isinstance(family, str) else list(family or [])
        found = _covopt.catalog_find(self._files, self._no_builtin, stress_at_25, bool(has_curve), families,
                                     name or "")
        return Found([Material(row) for row in found["materials"]], found["excluded_for_want_of_curve"])

    def __len__(self):
        return len(self._rows)

    def __repr__(self):
        parts = ([] if self._no_builtin else ["built-in"]) + self._files
        return f"Catalog({', '.join(parts)}: {len(self)} materials)"
