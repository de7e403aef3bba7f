<?xml version="1.0" encoding="UTF-8"?>
<tileset name="broken" tilewidth="16" tileheight="16" tilecount="4" columns="2">
 <image source="x.png" width="32" height="32">
</tileset>
