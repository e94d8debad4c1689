"""Root conftest: pytest only honours `pytest_plugins` here, so the outline plugin and every step module load
for every test below the repository root."""

from steps import STEP_MODULES

pytest_plugins = ["outline.plugin.pytest_plugin", *STEP_MODULES]
