// System control registers (hw/regs/sysctrl.json): identification, clock rate, scratch word, and in
// simulation the exit and putchar ports, which leave the SoC as one-cycle strobes for the harness.
module htx_sysctrl #(
  parameter int unsigned ClockHz = 12_000_000,
  parameter bit          Sim     = 1'b0
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        req_valid_i,
  output logic        req_ready_o,
  input  logic [31:0] req_addr_i,
  input  logic        req_we_i,
  input  logic [3:0]  req_be_i,
  input  logic [31:0] req_wdata_i,
  output logic        rsp_valid_o,
  output logic [31:0] rsp_rdata_o,
  output logic        rsp_err_o,

  output logic        sim_exit_o,      // strobe: firmware wrote SIM_EXIT (only when Sim)
  output logic [7:0]  sim_exit_code_o,
  output logic        sim_putchar_o,   // strobe: firmware wrote SIM_PUTCHAR (only when Sim)
  output logic [7:0]  sim_char_o
);
  logic [11:0] offset;
  logic        write;
  logic [31:0] scratch_q, rdata_d, rsp_rdata_q;
  logic        rsp_valid_q;

  logic unused_addr;
  assign unused_addr = ^{req_addr_i[31:12], req_addr_i[1:0]};
  // Registers are decoded by word: a byte or half-word access reaches its word's lanes.
  assign offset      = {req_addr_i[11:2], 2'b00};
  assign req_ready_o = 1'b1;
  assign write       = req_valid_i && req_we_i;

  always_comb begin
    rdata_d = '0;
    unique case (offset)
      htx_sysctrl_reg_pkg::SYSCTRL_ID_OFFSET:       rdata_d = htx_sysctrl_reg_pkg::SYSCTRL_ID_RESET;
      htx_sysctrl_reg_pkg::SYSCTRL_VERSION_OFFSET:  rdata_d = htx_sysctrl_reg_pkg::SYSCTRL_VERSION_RESET;
      htx_sysctrl_reg_pkg::SYSCTRL_CLOCK_HZ_OFFSET: rdata_d = 32'(ClockHz);
      htx_sysctrl_reg_pkg::SYSCTRL_SCRATCH_OFFSET:  rdata_d = scratch_q;
      htx_sysctrl_reg_pkg::SYSCTRL_PLATFORM_OFFSET:
        rdata_d[htx_sysctrl_reg_pkg::SYSCTRL_PLATFORM_SIM_LSB] = Sim;
      default: ;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      scratch_q       <= htx_sysctrl_reg_pkg::SYSCTRL_SCRATCH_RESET;
      rsp_valid_q     <= 1'b0;
      rsp_rdata_q     <= '0;
      sim_exit_o      <= 1'b0;
      sim_exit_code_o <= '0;
      sim_putchar_o   <= 1'b0;
      sim_char_o      <= '0;
    end else begin
      rsp_valid_q   <= req_valid_i;
      if (req_valid_i && !req_we_i) rsp_rdata_q <= rdata_d;
      sim_exit_o    <= 1'b0;
      sim_putchar_o <= 1'b0;
      if (write) begin
        unique case (offset)
          htx_sysctrl_reg_pkg::SYSCTRL_SCRATCH_OFFSET: begin
            for (int i = 0; i < 4; i++) begin
              if (req_be_i[i]) scratch_q[i*8 +: 8] <= req_wdata_i[i*8 +: 8];
            end
          end
          htx_sysctrl_reg_pkg::SYSCTRL_SIM_EXIT_OFFSET: begin
            sim_exit_o      <= Sim && req_be_i[0];
            sim_exit_code_o <= req_wdata_i[7:0];
          end
          htx_sysctrl_reg_pkg::SYSCTRL_SIM_PUTCHAR_OFFSET: begin
            sim_putchar_o <= Sim && req_be_i[0];
            sim_char_o    <= req_wdata_i[7:0];
          end
          default: ;
        endcase
      end
    end
  end

  assign rsp_valid_o = rsp_valid_q;
  assign rsp_rdata_o = rsp_rdata_q;
  assign rsp_err_o   = 1'b0;
endmodule
