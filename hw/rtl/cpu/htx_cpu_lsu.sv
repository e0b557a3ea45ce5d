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
  // load lane decode (execute stage), registered into write-back
  input  logic        req_load_i,
  input  logic        req_signed_i,   // LB, LH
  output htx_cpu_pkg::load_sel_t req_sel_o,
  // response side (write-back stage)
  input  htx_cpu_pkg::load_sel_t rsp_sel_i,
  input  logic [31:0] rsp_rdata_i,    // whole bus word
  output logic [31:0] rsp_value_o     // the extended value, 0 unless rsp_sel_i is a load's
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

  // Response selects. Word loads have offset 0 and half-word loads offset 0 or 2 (decode traps
  // the others), so bits 7:0 are always the lane at the offset and a half-word's sign is in the
  // next lane.
  always_comb begin
    req_sel_o = '0;
    for (int k = 0; k < 4; k++) begin
      req_sel_o.lane[k] = req_load_i && (req_offset_i == k[1:0]);
      req_sel_o.sign[k] = req_load_i && req_signed_i &&
                          (((req_size_i == 2'b00) && (req_offset_i == k[1:0])) ||
                           ((req_size_i == 2'b01) && (req_offset_i + 2'd1 == k[1:0])));
    end
    req_sel_o.mid_lo   = req_load_i && (req_size_i != 2'b00) && !req_offset_i[1];
    req_sel_o.mid_hi   = req_load_i && (req_size_i == 2'b01) && req_offset_i[1];
    req_sel_o.mid_fill = req_load_i && (req_size_i == 2'b00);
    req_sel_o.word     = req_load_i && req_size_i[1];
  end

  // Response, arranged for depth: the bus word arrives late in W, and the register file writes it
  // half a cycle later (on the falling edge). Every select is a flip-flop, so the fill (an AND-OR of
  // four candidate sign bits) is two LUT levels after the bus and every result bit at most one more.
  (* keep *) logic rsp_fill;
  assign rsp_fill = |(rsp_sel_i.sign & {rsp_rdata_i[31], rsp_rdata_i[23], rsp_rdata_i[15],
                                        rsp_rdata_i[7]});
  always_comb begin
    rsp_value_o[7:0]   = ({8{rsp_sel_i.lane[0]}} & rsp_rdata_i[7:0]) |
                         ({8{rsp_sel_i.lane[1]}} & rsp_rdata_i[15:8]) |
                         ({8{rsp_sel_i.lane[2]}} & rsp_rdata_i[23:16]) |
                         ({8{rsp_sel_i.lane[3]}} & rsp_rdata_i[31:24]);
    rsp_value_o[15:8]  = ({8{rsp_sel_i.mid_lo}} & rsp_rdata_i[15:8]) |
                         ({8{rsp_sel_i.mid_hi}} & rsp_rdata_i[31:24]) |
                         {8{rsp_sel_i.mid_fill && rsp_fill}};
    // (The fill is 0 for word loads: no sign select is set.)
    rsp_value_o[31:16] = ({16{rsp_sel_i.word}} & rsp_rdata_i[31:16]) | {16{rsp_fill}};
  end

endmodule
