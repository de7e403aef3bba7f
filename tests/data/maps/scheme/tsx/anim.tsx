<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.11.0" name="anim" class="terrain" tilewidth="16" tileheight="16" spacing="1" margin="2" tilecount="8" columns="4">
 <tileoffset x="0" y="4"/>
 <properties>
  <property name="kind" value="rock"/>
 </properties>
 <image source="../art/tiles.png" width="70" height="36"/>
 <tile id="0">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="water">
  <animation>
   <frame tileid="1" duration="100"/>
   <frame tileid="2" duration="150"/>
  </animation>
 </tile>
</tileset>
