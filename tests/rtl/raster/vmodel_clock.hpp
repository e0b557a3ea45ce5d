// Clocking for the unit tests that Verilate one module alone (the multiplier, the counter bank, the
// reciprocal unit): every such top has clk_i and an active-low rst_ni.
#pragma once

namespace htx::raster_test {

// Resets the model with clk_i low: the caller sets its other inputs first.
template <class V>
void reset_model(V& m) {
  m.clk_i = 0;
  m.rst_ni = 0;
  m.eval();
  m.rst_ni = 1;
  m.eval();
}

// One rising and falling clock edge with the inputs as they are.
template <class V>
void clock_edge(V& m) {
  m.clk_i = 1;
  m.eval();
  m.clk_i = 0;
  m.eval();
}

}  // namespace htx::raster_test
