MODULE ShelfLoad
    ! generator: gen-rapid 0.1.0
    ! cell: shelf.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 15.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 34
    ! min clearance (mm): 15.0
    ! estimated time (s): 12.85

    CONST jointtarget home := [[0.000,-20.000,20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[-6.000,-20.000,24.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[-11.000,-15.000,29.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[-40.000,24.000,29.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[-35.000,41.000,29.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_05 := [[-33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_06 := [[-25.000,65.000,8.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lower_right := [[-25.000,65.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[-26.000,59.000,14.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_02 := [[-33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_03 := [[-35.000,42.000,28.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_04 := [[-42.115,24.242,28.492,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_05 := [[-51.938,12.188,17.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_06 := [[-44.000,2.000,5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_07 := [[-34.000,12.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget upper_right := [[-25.000,20.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[-13.000,-13.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[0.000,-26.000,-18.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[16.000,-10.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget upper_left := [[25.000,20.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[39.000,5.000,1.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_02 := [[43.000,1.000,5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_03 := [[53.000,11.000,16.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_04 := [[36.000,29.000,34.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_05 := [[33.000,48.000,25.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_06 := [[33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_07 := [[25.000,65.000,8.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lower_left := [[25.000,65.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[26.000,59.000,14.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[35.000,42.000,28.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_04 := [[31.875,25.750,32.750,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_05 := [[10.000,-16.000,30.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_06 := [[3.000,-23.000,23.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home_again := [[0.000,-20.000,20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ lower_right\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_07\NoEOffs, v500, fine, tool0;
        MoveAbsJ upper_right\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ upper_left\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_07\NoEOffs, v500, fine, tool0;
        MoveAbsJ lower_left\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ home_again\NoEOffs, v500, fine, tool0;
    ENDPROC
ENDMODULE
