"""The registry of the bearing fidelities: name -> its contract (models.fidelity.Fidelity).

A new fidelity adds its facade and its `FIDELITY` under models/, its declarations, its scene rules
(scene.FIDELITY_RULES) and one entry here; the FMU layer, the build and the README's table loop over this
registry and need no change.
"""

from .models import analytic, quasi_static
from .models.dem import model as dem

FIDELITIES = {fidelity.name: fidelity for fidelity in (analytic.FIDELITY, quasi_static.FIDELITY, dem.FIDELITY)}
