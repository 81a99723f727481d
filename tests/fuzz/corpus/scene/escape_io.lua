io.open('../escape_io', 'w'):write('x')
