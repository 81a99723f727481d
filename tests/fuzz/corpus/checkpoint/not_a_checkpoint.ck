shear_rate,stress
1,2
