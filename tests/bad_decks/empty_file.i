# expect: 1: the deck is empty
# only comments: nothing to run

   
