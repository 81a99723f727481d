local h = require 'hearth'
h.write('../escape_write', 'x')
