"""The component library, by domain (shaped like the Modelica Standard Library)."""
