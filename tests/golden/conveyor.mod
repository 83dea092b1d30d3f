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
    ! moves: 7
    ! min clearance (mm): 25.1
    ! estimated time (s): 7.80
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 4 (via zone fine)

    CONST jointtarget ready := [[-10.000,-10.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[-10.000,-14.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[48.000,-14.000,-20.000,0.000,48.980,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick := [[120.500,15.250,25.125,0.000,55.500,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[118.598,-19.725,25.993,0.070,55.531,-0.105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_02 := [[-60.000,-20.000,26.000,9.972,59.987,-14.958],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget place := [[-59.750,18.500,22.250,10.000,60.000,-15.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget ready2 := [[-10.000,-10.000,-20.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ ready\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v1000, fine, tool0;
        MoveAbsJ pick\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v1000, fine, tool0;
        MoveAbsJ via02_02\NoEOffs, v1000, fine, tool0;
        MoveAbsJ place\NoEOffs, v1000, fine, tool0;
        MoveAbsJ ready2\NoEOffs, v1000, fine, tool0;
    ENDPROC
ENDMODULE
