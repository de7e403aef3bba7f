<?xml version="1.0" encoding="UTF-8"?>
<tileset name="broken" tilewidth="16" tileheight="16" tilecount="many" columns="2">
</tileset>
