# expect: 4: include cycle
# the deck includes itself
begin sierra cyc
  include include_cycle.i
end sierra cyc
