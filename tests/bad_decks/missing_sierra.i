# expect: 3: cannot stand at the top of the file
# no begin sierra
begin presto procedure p
end presto procedure p
