"""Andrews' squeezing mechanism's parameters and start (E. Hairer, G. Wanner, the test set's
values; zeitner-scenes/src/andrews.rs), shared by the peer scripts."""

M = (0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498)
I = (2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5)
XA, YA, XB, YB, XC, YC = -0.06934, -0.00227, -0.03635, 0.03273, 0.014, 0.072
C0, L0, MOM = 4530.0, 0.07785, 0.033
D, DA, E, EA, RR, RA, SS = 0.028, 0.0115, 0.02, 0.01421, 0.007, 0.00092, 0.035
SA, SB, SC, SD, TA, TB, U = 0.01874, 0.01043, 0.018, 0.02, 0.02308, 0.00916, 0.04
UA, UB, ZF, ZT, FA = 0.01228, 0.00449, 0.02, 0.04, 0.01421
