"""Examples of the signal blocks; ``msl`` holds those of Modelica.Blocks.Examples."""
