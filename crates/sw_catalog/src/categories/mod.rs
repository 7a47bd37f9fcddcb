//! The categories, one module per family. `ALL` is the registry, in a stable order.

mod agriculture;
mod blocks;
mod building;
mod care;
mod containers;
mod datacentre;
mod electronics;
mod furniture;
mod garage;
mod gases;
mod industrial;
mod kit;
mod kitchen;
mod lab;
mod machine_tools;
mod office;
mod parts;
mod robot_bases;
mod safety;
mod shapes;
mod stationery;
mod storage;
mod tableware;
mod vehicles;

use crate::Category;

pub(crate) static ALL: &[Category] = &[
    furniture::TABLE,
    containers::CARDBOARD_BOX,
    furniture::WORKBENCH,
    storage::SHELF,
    storage::PALLET_RACK,
    containers::CRATE,
    containers::BIN,
    containers::PALLET,
    industrial::CONVEYOR,
    storage::CABINET,
    industrial::ELECTRICAL_PANEL,
    furniture::CHAIR,
    industrial::MACHINE,
    robot_bases::PEDESTAL,
    robot_bases::MOBILE_CART,
    tableware::MUG,
    tableware::CUP,
    tableware::PLATE,
    tableware::BOWL,
    tableware::BOTTLE,
    tableware::DRINK_CAN,
    tableware::TRAY,
    office::DESK,
    office::FILING_CABINET,
    office::WHITEBOARD,
    office::WATER_COOLER,
    containers::DRUM,
    containers::TRASH_CAN,
    furniture::DINING_TABLE,
    furniture::STOOL,
    furniture::SOFA,
    blocks::CUBE,
    blocks::CYLINDER,
    blocks::SPHERE,
    kitchen::COUNTER,
    kitchen::SINK,
    kitchen::FRIDGE,
    kitchen::STOVE,
    kitchen::MICROWAVE,
    electronics::MONITOR,
    electronics::LAPTOP,
    electronics::KEYBOARD,
    electronics::PRINTER,
    electronics::DESK_LAMP,
    electronics::PHONE,
    stationery::BOOK,
    stationery::PEN,
    stationery::STAPLER,
    storage::BOOKSHELF,
    storage::GONDOLA_SHELF,
    storage::LOCKER,
    lab::FUME_HOOD,
    lab::MICROSCOPE,
    lab::CENTRIFUGE,
    lab::TEST_TUBE_RACK,
    lab::BEAKER,
    safety::FIRE_EXTINGUISHER,
    safety::EYEWASH_STATION,
    safety::SAFETY_FENCE,
    safety::WELDING_SCREEN,
    safety::TRAFFIC_CONE,
    building::DOOR,
    building::ROLL_UP_DOOR,
    building::WINDOW,
    building::LADDER,
    datacentre::SERVER_RACK,
    datacentre::SWITCHGEAR,
    datacentre::TRANSFORMER,
    datacentre::COOLING_UNIT,
    datacentre::CABLE_TRAY,
    vehicles::FORKLIFT,
    vehicles::PALLET_JACK,
    vehicles::HAND_TRUCK,
    vehicles::CART,
    vehicles::SHOPPING_CART,
    garage::TOOL_CHEST,
    garage::AIR_COMPRESSOR,
    garage::CAR_LIFT,
    garage::TIRE,
    machine_tools::LATHE,
    machine_tools::DRILL_PRESS,
    machine_tools::FDM_PRINTER,
    gases::GAS_CYLINDER,
    gases::GAS_CYLINDER_RACK,
    agriculture::POTTED_PLANT,
    agriculture::PLANTER_BOX,
    agriculture::SEEDLING_TRAY,
    agriculture::HAY_BALE,
    agriculture::FEED_SACK,
    care::HOSPITAL_BED,
    care::IV_POLE,
    care::CHECKOUT_COUNTER,
    care::VENDING_MACHINE,
];
