begin sierra a\
 b
  x = 1 nm # c
$ d
end
