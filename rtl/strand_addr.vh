// strand_addr.vh - the walk from one node to the next, written once; included in the
// body of every module that walks the nodes in {unit, node} order (needs K, UW, IW).
localparam integer ADDR_K_LAST_I = K - 1;
localparam [IW-1:0] ADDR_K_LAST = ADDR_K_LAST_I[IW-1:0];

// The {unit, node} address after a: the next node of its unit, or node 0 of the next unit.
function [UW+IW-1:0] next_node(input [UW+IW-1:0] a);
    next_node = a[IW-1:0] == ADDR_K_LAST ? {a[UW+IW-1:IW] + 1'b1, {IW{1'b0}}} : a + 1'b1;
endfunction
