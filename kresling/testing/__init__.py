"""Reference implementations the package's tests and studies compare it with: not the
package's own methods, but independent ones, written again from their published equations.

- :mod:`kresling.testing.origami_simulator`: Origami Simulator's model (bars, creases and
  face springs, damped explicit dynamics) on any crease pattern;
- :mod:`kresling.testing.origami_simulator_page`: what Origami Simulator's own importer
  reads and builds from a file, run in headless Chromium;
- :mod:`kresling.testing.one_layer_kresling`: a one-layer Kresling built by hand, whose MGDCM
  path crosses a double bifurcation.
"""
