// The ULX3S's clocks (docs/boards.md): the SoC's 25 MHz, which is also the pixel clock of 640x480
// at 60 Hz, and the DVI serialisers' 125 MHz (five times it: ten bits a pixel on DDR outputs).
// With HTX_ECP5 (the board's build) both come from one ECP5 PLL (EHXPLLL: VCO 625 MHz = 25 MHz x
// CLKFB_DIV 5 x CLKOP_DIV 5; CLKOP / 5 = 125 MHz, CLKOS / 25 = 25 MHz), so the two are
// phase-related; locked_o is the PLL's lock. Elsewhere (Verilator, lint) the 25 MHz input is the
// SoC's clock, there is no serial clock (the DVI serialisers do not run) and locked_o is 1.
module htx_ulx3s_clocks (
  input  logic clk_25mhz_i,
  output logic clk_sys_o,     // 25 MHz
  output logic clk_shift_o,   // 125 MHz
  output logic locked_o
);
`ifdef HTX_ECP5
  logic clkop, clkos;
  // The loop filter's settings, as Lattice's tools and ecppll write them: nextpnr writes 0 for
  // each one that is not given, which is no charge-pump current and no filter resistor.
  (* FREQUENCY_PIN_CLKI="25" *) (* FREQUENCY_PIN_CLKOP="125" *) (* FREQUENCY_PIN_CLKOS="25" *)
  (* ICP_CURRENT="12" *) (* LPF_RESISTOR="8" *) (* MFG_ENABLE_FILTEROPAMP="1" *) (* MFG_GMCREF_SEL="2" *)
  EHXPLLL #(
    .PLLRST_ENA("DISABLED"), .INTFB_WAKE("DISABLED"), .STDBY_ENABLE("DISABLED"),
    .DPHASE_SOURCE("DISABLED"), .OUTDIVIDER_MUXA("DIVA"), .OUTDIVIDER_MUXB("DIVB"),
    .OUTDIVIDER_MUXC("DIVC"), .OUTDIVIDER_MUXD("DIVD"),
    .CLKI_DIV(1), .CLKFB_DIV(5), .FEEDBK_PATH("CLKOP"),
    .CLKOP_ENABLE("ENABLED"), .CLKOP_DIV(5), .CLKOP_CPHASE(2), .CLKOP_FPHASE(0),
    .CLKOS_ENABLE("ENABLED"), .CLKOS_DIV(25), .CLKOS_CPHASE(12), .CLKOS_FPHASE(0)
  ) u_pll (
    .RST(1'b0), .STDBY(1'b0), .CLKI(clk_25mhz_i), .CLKOP(clkop), .CLKOS(clkos), .CLKOS2(),
    .CLKOS3(), .CLKFB(clkop), .CLKINTFB(), .PHASESEL0(1'b0), .PHASESEL1(1'b0),
    .PHASEDIR(1'b1), .PHASESTEP(1'b1), .PHASELOADREG(1'b1), .PLLWAKESYNC(1'b0),
    .ENCLKOP(1'b0), .ENCLKOS(1'b0), .ENCLKOS2(1'b0), .ENCLKOS3(1'b0), .LOCK(locked_o),
    .INTLOCK(), .REFCLK()
  );
  assign clk_sys_o   = clkos;
  assign clk_shift_o = clkop;
`else
  assign clk_sys_o   = clk_25mhz_i;
  assign clk_shift_o = 1'b0;
  assign locked_o    = 1'b1;
`endif
endmodule
