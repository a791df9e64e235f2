package jade.domain.FIPAAgentManagement;

/** The symbols of FIPA's agent-management ontology, as JADE names them. */
public interface FIPAManagementVocabulary {
    /** FIPA: {@code NAME}. */
    String NAME = "FIPA-Agent-Management";
    /** FIPA: {@code DFAGENTDESCRIPTION}. */
    String DFAGENTDESCRIPTION = "df-agent-description";
    /** FIPA: {@code DFAGENTDESCRIPTION_NAME}. */
    String DFAGENTDESCRIPTION_NAME = "name";
    /** FIPA: {@code DFAGENTDESCRIPTION_SERVICES}. */
    String DFAGENTDESCRIPTION_SERVICES = "services";
    /** FIPA: {@code DFAGENTDESCRIPTION_PROTOCOLS}. */
    String DFAGENTDESCRIPTION_PROTOCOLS = "protocols";
    /** FIPA: {@code DFAGENTDESCRIPTION_ONTOLOGIES}. */
    String DFAGENTDESCRIPTION_ONTOLOGIES = "ontologies";
    /** FIPA: {@code DFAGENTDESCRIPTION_LANGUAGES}. */
    String DFAGENTDESCRIPTION_LANGUAGES = "languages";
    /** FIPA: {@code DFAGENTDESCRIPTION_LEASE_TIME}. */
    String DFAGENTDESCRIPTION_LEASE_TIME = "lease-time";
    /** FIPA: {@code SERVICEDESCRIPTION}. */
    String SERVICEDESCRIPTION = "service-description";
    /** FIPA: {@code SERVICEDESCRIPTION_NAME}. */
    String SERVICEDESCRIPTION_NAME = "name";
    /** FIPA: {@code SERVICEDESCRIPTION_TYPE}. */
    String SERVICEDESCRIPTION_TYPE = "type";
    /** FIPA: {@code SERVICEDESCRIPTION_OWNERSHIP}. */
    String SERVICEDESCRIPTION_OWNERSHIP = "ownership";
    /** FIPA: {@code SERVICEDESCRIPTION_PROTOCOLS}. */
    String SERVICEDESCRIPTION_PROTOCOLS = "protocols";
    /** FIPA: {@code SERVICEDESCRIPTION_ONTOLOGIES}. */
    String SERVICEDESCRIPTION_ONTOLOGIES = "ontologies";
    /** FIPA: {@code SERVICEDESCRIPTION_LANGUAGES}. */
    String SERVICEDESCRIPTION_LANGUAGES = "languages";
    /** FIPA: {@code SERVICEDESCRIPTION_PROPERTIES}. */
    String SERVICEDESCRIPTION_PROPERTIES = "properties";
    /** FIPA: {@code SEARCHCONSTRAINTS}. */
    String SEARCHCONSTRAINTS = "search-constraints";
    /** FIPA: {@code SEARCHCONSTRAINTS_MAX_DEPTH}. */
    String SEARCHCONSTRAINTS_MAX_DEPTH = "max-depth";
    /** FIPA: {@code SEARCHCONSTRAINTS_MAX_RESULTS}. */
    String SEARCHCONSTRAINTS_MAX_RESULTS = "max-results";
    /** FIPA: {@code SEARCHCONSTRAINTS_SEARCH_ID}. */
    String SEARCHCONSTRAINTS_SEARCH_ID = "search-id";
    /** FIPA: {@code AMSAGENTDESCRIPTION}. */
    String AMSAGENTDESCRIPTION = "ams-agent-description";
    /** FIPA: {@code AMSAGENTDESCRIPTION_NAME}. */
    String AMSAGENTDESCRIPTION_NAME = "name";
    /** FIPA: {@code AMSAGENTDESCRIPTION_OWNERSHIP}. */
    String AMSAGENTDESCRIPTION_OWNERSHIP = "ownership";
    /** FIPA: {@code AMSAGENTDESCRIPTION_STATE}. */
    String AMSAGENTDESCRIPTION_STATE = "state";
    /** FIPA: {@code PROPERTY}. */
    String PROPERTY = "property";
    /** FIPA: {@code PROPERTY_NAME}. */
    String PROPERTY_NAME = "name";
    /** FIPA: {@code PROPERTY_VALUE}. */
    String PROPERTY_VALUE = "value";
    /** FIPA: {@code MULTI_VALUE_PROPERTY}. */
    String MULTI_VALUE_PROPERTY = "multi-value-property";
    /** FIPA: {@code ENVELOPE}. */
    String ENVELOPE = "envelope";
    /** FIPA: {@code ENVELOPE_TO}. */
    String ENVELOPE_TO = "to";
    /** FIPA: {@code ENVELOPE_FROM}. */
    String ENVELOPE_FROM = "from";
    /** FIPA: {@code ENVELOPE_COMMENTS}. */
    String ENVELOPE_COMMENTS = "comments";
    /** FIPA: {@code ENVELOPE_ACLREPRESENTATION}. */
    String ENVELOPE_ACLREPRESENTATION = "acl-representation";
    /** FIPA: {@code ENVELOPE_PAYLOADLENGTH}. */
    String ENVELOPE_PAYLOADLENGTH = "payload-length";
    /** FIPA: {@code ENVELOPE_PAYLOADENCODING}. */
    String ENVELOPE_PAYLOADENCODING = "payload-encoding";
    /** FIPA: {@code ENVELOPE_DATE}. */
    String ENVELOPE_DATE = "date";
    /** FIPA: {@code ENVELOPE_INTENDEDRECEIVER}. */
    String ENVELOPE_INTENDEDRECEIVER = "intended-receiver";
    /** FIPA: {@code ENVELOPE_TRANSPORTBEHAVIOUR}. */
    String ENVELOPE_TRANSPORTBEHAVIOUR = "transport-behaviour";
    /** FIPA: {@code ENVELOPE_RECEIVED}. */
    String ENVELOPE_RECEIVED = "received";
    /** FIPA: {@code ENVELOPE_PROPERTIES}. */
    String ENVELOPE_PROPERTIES = "properties";
    /** FIPA: {@code RECEIVEDOBJECT}. */
    String RECEIVEDOBJECT = "received-object";
    /** FIPA: {@code RECEIVEDOBJECT_BY}. */
    String RECEIVEDOBJECT_BY = "by";
    /** FIPA: {@code RECEIVEDOBJECT_FROM}. */
    String RECEIVEDOBJECT_FROM = "from";
    /** FIPA: {@code RECEIVEDOBJECT_DATE}. */
    String RECEIVEDOBJECT_DATE = "date";
    /** FIPA: {@code RECEIVEDOBJECT_ID}. */
    String RECEIVEDOBJECT_ID = "id";
    /** FIPA: {@code RECEIVEDOBJECT_VIA}. */
    String RECEIVEDOBJECT_VIA = "via";
    /** FIPA: {@code APDESCRIPTION}. */
    String APDESCRIPTION = "ap-description";
    /** FIPA: {@code APDESCRIPTION_NAME}. */
    String APDESCRIPTION_NAME = "name";
    /** FIPA: {@code APDESCRIPTION_SERVICES}. */
    String APDESCRIPTION_SERVICES = "ap-services";
    /** FIPA: {@code APSERVICE}. */
    String APSERVICE = "ap-service";
    /** FIPA: {@code APSERVICE_NAME}. */
    String APSERVICE_NAME = "name";
    /** FIPA: {@code APSERVICE_TYPE}. */
    String APSERVICE_TYPE = "type";
    /** FIPA: {@code APSERVICE_ADDRESSES}. */
    String APSERVICE_ADDRESSES = "addresses";
    /** FIPA: {@code REGISTER}. */
    String REGISTER = "register";
    /** FIPA: {@code REGISTER_DESCRIPTION}. */
    String REGISTER_DESCRIPTION = "description";
    /** FIPA: {@code DEREGISTER}. */
    String DEREGISTER = "deregister";
    /** FIPA: {@code DEREGISTER_DESCRIPTION}. */
    String DEREGISTER_DESCRIPTION = "description";
    /** FIPA: {@code MODIFY}. */
    String MODIFY = "modify";
    /** FIPA: {@code MODIFY_DESCRIPTION}. */
    String MODIFY_DESCRIPTION = "description";
    /** FIPA: {@code SEARCH}. */
    String SEARCH = "search";
    /** FIPA: {@code SEARCH_DESCRIPTION}. */
    String SEARCH_DESCRIPTION = "description";
    /** FIPA: {@code SEARCH_CONSTRAINTS}. */
    String SEARCH_CONSTRAINTS = "constraints";
    /** FIPA: {@code GETDESCRIPTION}. */
    String GETDESCRIPTION = "get-description";
    /** FIPA: {@code ALREADYREGISTERED}. */
    String ALREADYREGISTERED = "already-registered";
    /** FIPA: {@code NOTREGISTERED}. */
    String NOTREGISTERED = "not-registered";
}
