// The multiples 0..N of a step, as the segment unit's golden model forms them (host/units/segment.cpp):
// an even multiple is its half shifted one bit (wiring), an odd one the previous multiple plus the step
// (one W-bit adder, wrapping). mult[i*W +: W] = i * step modulo 2^W. Adders: the odd multiples from 3 up.
module ps_multiples #(
  parameter W = 24,
  parameter N = 4
) (
  input  wire [W-1:0]       step,
  output wire [(N+1)*W-1:0] mult
);
  /* verilator lint_off UNOPTFLAT */
  wire [(N+1)*W-1:0] m;
  /* verilator lint_on UNOPTFLAT */
  assign m[W-1:0] = {W{1'b0}};
  genvar i;
  generate
    for (i = 1; i <= N; i = i + 1) begin : multiple
      if (i == 1) begin : one
        assign m[W +: W] = step;
      end else if (i % 2 == 0) begin : shift
        assign m[i*W +: W] = {m[(i/2)*W +: W-1], 1'b0};
      end else begin : add
        assign m[i*W +: W] = m[(i-1)*W +: W] + step;
      end
    end
  endgenerate
  assign mult = m;
endmodule
