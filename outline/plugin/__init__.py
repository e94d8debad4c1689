"""The pytest side: the plugin (tags -> marks, --item/--req selection, report labels), feature binding, step
definitions and the step index."""
