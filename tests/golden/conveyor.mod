MODULE ConveyorPick
    ! generator: gen-rapid 0.1.0
    ! cell: conveyor.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: depth-first
    ! grid (deg): 2.000
    ! clearance (mm): 25.0
    ! base: [250.0, -300.0, 0.0] yaw: -30.000
    ! moves: 16
    ! min clearance (mm): 26.4
    ! estimated time (s): 10.91
    ! zoned vias: 0 of 13 (via zone fine)
    ! the paper's method alone: 16 moves, 10.91 s

    CONST jointtarget ready := [[-10.000,-10.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[-10.000,-14.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[48.000,-14.000,-20.000,0.000,48.980,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[48.000,-14.000,26.000,0.000,50.086,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[48.000,16.000,26.000,0.000,50.489,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_05 := [[120.000,16.000,26.000,0.000,55.496,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick := [[120.500,15.250,25.125,0.000,55.500,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[120.000,16.000,26.000,0.028,55.512,-0.042],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_02 := [[120.000,-20.000,26.000,0.000,55.500,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_03 := [[-60.000,-20.000,26.000,9.972,59.987,-14.958],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_04 := [[-60.000,-20.000,22.000,9.976,59.989,-14.963],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_05 := [[-60.000,18.000,22.000,10.000,60.000,-15.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget place := [[-59.750,18.500,22.250,10.000,60.000,-15.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[-60.000,18.000,22.000,9.976,59.963,-14.963],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[-60.000,-10.000,22.000,8.402,57.604,-12.604],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[-60.000,-10.000,-20.000,4.904,52.356,-7.356],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget ready2 := [[-10.000,-10.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ ready\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_04\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_05\NoEOffs, v1000, fine, tool0;
        MoveAbsJ pick\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_02\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_03\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_04\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_05\NoEOffs, v1000, fine, tool0;
        MoveAbsJ place\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via03_03\NoEOffs, v1000, fine, tool0;
        MoveAbsJ ready2\NoEOffs, v1000, fine, tool0;
    ENDPROC
ENDMODULE
