// Load/store datapath (combinational): byte enables and store data placed on its lanes for the
// request (misalignment is checked in decode); lane selection and sign/zero extension for the
// response.
module htx_cpu_lsu (
  // request side (execute stage)
  input  logic [1:0]  req_size_i,     // funct3[1:0] of the load or store: byte, half, word
  input  logic [1:0]  req_offset_i,   // address bits [1:0]
  input  logic [31:0] req_data_i,     // rs2 of a store
  output logic [3:0]  req_be_o,
  output logic [31:0] req_wdata_o,
  // response side (write-back stage)
  input  logic [2:0]  rsp_funct3_i,
  input  logic [1:0]  rsp_offset_i,   // address bits [1:0] of the load
  input  logic [31:0] rsp_rdata_i,    // whole bus word
  output logic [31:0] rsp_value_o
);

  always_comb begin
    unique case (req_size_i)
      2'b00: begin
        req_be_o         = 4'b0001 << req_offset_i;
        req_wdata_o      = {4{req_data_i[7:0]}};
      end
      2'b01: begin
        req_be_o         = req_offset_i[1] ? 4'b1100 : 4'b0011;
        req_wdata_o      = {2{req_data_i[15:0]}};
      end
      default: begin
        req_be_o         = 4'b1111;
        req_wdata_o      = req_data_i;
      end
    endcase
  end

  // The addressed byte or half-word moved to bits [15:0].
  logic [15:0] shifted;
  always_comb begin
    unique case (rsp_offset_i)
      2'b00:   shifted = rsp_rdata_i[15:0];
      2'b01:   shifted = {8'b0, rsp_rdata_i[15:8]};
      2'b10:   shifted = rsp_rdata_i[31:16];
      default: shifted = {8'b0, rsp_rdata_i[31:24]};
    endcase
  end

  always_comb begin
    unique case (rsp_funct3_i)
      3'b000:  rsp_value_o = {{24{shifted[7]}}, shifted[7:0]};
      3'b001:  rsp_value_o = {{16{shifted[15]}}, shifted[15:0]};
      3'b100:  rsp_value_o = {24'b0, shifted[7:0]};
      3'b101:  rsp_value_o = {16'b0, shifted[15:0]};
      default: rsp_value_o = rsp_rdata_i;
    endcase
  end

endmodule
