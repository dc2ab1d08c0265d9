# expect: 3: no such file
begin sierra inc
  include does_not_exist.inc
end sierra inc
